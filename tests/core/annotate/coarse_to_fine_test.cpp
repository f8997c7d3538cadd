#include "core/annotate/coarse_to_fine.h"

#include <gtest/gtest.h>

#include "core/features/feature_grid.h"
#include "core/features/feature_pipeline.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh_crop.h"
#include "support/analytic_meshes.h"
#include "support/untrained_models.h"

namespace sagrid {
namespace {

// A 2 m counter with a 6 cm tap near its left end: the small part on a large object.
Mesh counterWithTap() {
  Mesh mesh = test::box({-1.0f, -0.3f, 0.0f}, {1.0f, 0.3f, 0.9f});
  test::append(mesh, test::box({-0.83f, 0.17f, 0.9f}, {-0.77f, 0.23f, 1.2f}));
  return mesh;
}

const Eigen::Vector3f kTap{-0.8f, 0.2f, 1.1f};

ModelPrediction predictionAt(const std::vector<Eigen::Vector3f>& meshPoints,
                             const Normalization& normalization) {
  ModelPrediction p;
  for (const auto& m : meshPoints) {
    ExtractedPoint e;
    e.position = normalization.toNormalized(m);
    e.distance = 0.05f;
    p.points.push_back(e);
  }
  return p;
}

TEST(CoarseToFine, CropRegionIsThePointsBoxGrownByTheMarginInsideTheObject) {
  const Mesh mesh = counterWithTap();
  const Normalization n = Normalization::fromMesh(mesh);
  CoarseToFineOptions options;
  const auto box = cropRegion(predictionAt({kTap}, n), n, mesh.bounds(), options);
  ASSERT_TRUE(box.has_value());
  const float grow = options.margin * 2.0f;  // the counter is 2 m long
  EXPECT_NEAR(box->max().x(), kTap.x() + grow, 1e-5f);
  EXPECT_NEAR(box->min().y(), kTap.y() - grow, 1e-5f);
  EXPECT_NEAR(box->min().x(), -1.0f, 1e-5f);  // clipped to the object
  EXPECT_NEAR(box->max().z(), 1.2f, 1e-5f);
  EXPECT_TRUE(box->contains(kTap));
}

TEST(CoarseToFine, NoSecondPassWhenThePointsSpreadOverTheObject) {
  const Mesh mesh = counterWithTap();
  const Normalization n = Normalization::fromMesh(mesh);
  std::string why;
  EXPECT_FALSE(cropRegion(predictionAt({kTap, {0.9f, 0.0f, 0.9f}}, n), n, mesh.bounds(), {}, &why)
                   .has_value());
  EXPECT_EQ(why, "the points spread over most of the object");
  EXPECT_FALSE(cropRegion(ModelPrediction{}, n, mesh.bounds(), {}, &why).has_value());
}

TEST(CoarseToFine, CropPointsMapBackToTheObjectFrameExactly) {
  const Mesh mesh = counterWithTap();
  const Normalization object = Normalization::fromMesh(mesh);
  const Mesh crop = cropMesh(mesh, *cropRegion(predictionAt({kTap}, object), object,
                                               mesh.bounds(), {}));
  const Normalization cropFrame = Normalization::fromMesh(crop);
  for (const Eigen::Vector3f& p : {kTap, Eigen::Vector3f(-0.9f, 0.1f, 0.95f)}) {
    const Eigen::Vector3f inCrop = cropFrame.toNormalized(p);
    EXPECT_LT((object.toMesh(cropToObject(inCrop, cropFrame, object)) - p).norm(), 1e-5f);
  }
  // The crop's 64^3 grid resolves the tap about three times finer than the object's.
  EXPECT_GT(cropFrame.scale, 3.0f * object.scale);
}

TEST(CoarseToFine, SecondPassPointsLieInTheCropOnTheSurfaceOrFallBack) {
  const Mesh mesh = counterWithTap();
  FeatureOptions options;
  options.views = 12;
  const FeatureGrid grid = computeFeatures(mesh, options);
  const auto model = test::untrainedModelFor("sink.fluidsource", grid);
  const SurfaceScene scene(mesh);
  ModelPrediction coarse = predictionAt({kTap}, grid.normalization);
  coarse.field.resolution = grid.resolution;
  coarse.field.voxels = grid.voxels;
  coarse.field.distances.assign(grid.voxels.size(), 0.5f);
  std::string why = "unset";
  const ModelPrediction fine = refineInCrop(model, coarse, mesh, grid, scene, options,
                                            InstanceMode::Single, 1, 1, {}, &why);
  EXPECT_EQ(why, "");
  ASSERT_EQ(fine.points.size(), 1u);
  ASSERT_EQ(fine.surface.size(), 1u);
  const auto region = cropRegion(coarse, grid.normalization, mesh.bounds(), {});
  Eigen::AlignedBox3f slack = *region;
  slack.extend(region->min() - Eigen::Vector3f::Constant(0.05f));
  slack.extend(region->max() + Eigen::Vector3f::Constant(0.05f));
  EXPECT_TRUE(slack.contains(grid.normalization.toMesh(fine.points[0].position)));
  EXPECT_LT(test::bruteForceDistance(mesh, fine.surface[0].position), 1e-4f);
  EXPECT_EQ(fine.field.distances, coarse.field.distances);  // the GUI keeps the whole field

  CoarseToFineOptions tooFew;
  tooFew.minTriangles = 1000000;
  const ModelPrediction kept = refineInCrop(model, coarse, mesh, grid, scene, options,
                                            InstanceMode::Single, 1, 1, tooFew, &why);
  EXPECT_NE(why.find("triangles"), std::string::npos) << why;
  EXPECT_EQ(kept.points[0].position, coarse.points[0].position);
}

}  // namespace
}  // namespace sagrid
