// Bare glass hobs whose zones and touch controls are printed only in the texture.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/common/error.h"
#include "core/generate/dataset_generator.h"

namespace sagrid::gen {
namespace {

const GeneratorOptions kAllGlassHobs{0.0, 1.0};

// The largest luminance the top's texture shows within `radius` metres of `p`.
float brightestNear(const GeneratedObject& object, const Eigen::Vector3f& p, float radius) {
  const Mesh& mesh = object.mesh;
  const Texture* texture = nullptr;
  for (const Material& m : mesh.materials)
    if (m.texture >= 0) texture = &mesh.textures.at(static_cast<std::size_t>(m.texture));
  EXPECT_NE(texture, nullptr);
  if (!texture) return 0.0f;
  // The printed quad spans UV [0,1]²; find its extent from the vertices that carry UVs (0,0) and
  // (1,1).
  Eigen::Vector2f lo = Eigen::Vector2f::Zero(), hi = Eigen::Vector2f::Zero();
  for (std::size_t v = 0; v < mesh.uvs.size(); ++v) {
    if (mesh.uvs[v] == Eigen::Vector2f(0, 0)) lo = mesh.positions[v].head<2>();
    if (mesh.uvs[v] == Eigen::Vector2f(1, 1)) hi = mesh.positions[v].head<2>();
  }
  float best = 0.0f;
  for (float dx = -radius; dx <= radius; dx += 0.0005f) {
    for (float dy = -radius; dy <= radius; dy += 0.0005f) {
      const Eigen::Vector2f uv =
          (p.head<2>() + Eigen::Vector2f(dx, dy) - lo).cwiseQuotient(hi - lo);
      if (uv.minCoeff() < 0 || uv.maxCoeff() > 1) continue;
      best = std::max(best, texture->sample(uv).mean());
    }
  }
  return best;
}

TEST(GlassHobs, ZeroShareWritesTheBenchLookUnchanged) {
  for (int i = 0; i < 8; ++i) {
    const FinishedObject plain = makeObject("stove", 41, i, MeshFormat::Obj);
    const FinishedObject zero =
        makeObject("stove", 41, i, MeshFormat::Obj, GeneratorOptions{0.0, 0.0});
    EXPECT_EQ(plain.mesh.positions, zero.mesh.positions);
    EXPECT_EQ(plain.mesh.triangles, zero.mesh.triangles);
  }
}

TEST(GlassHobs, ASlabHasNoBodyAndItsControlsArePrintedWhereItsPointsAre) {
  int withCluster = 0;
  for (int i = 0; i < 24; ++i) {
    const GeneratedObject hob = makeRawObject("stove", 42, i, kAllGlassHobs);
    ASSERT_EQ(hob.generator.at("kind"), "glass_slab") << i;
    EXPECT_EQ(hob.generator.at("controls"), "printed");
    const Eigen::AlignedBox3f box = hob.mesh.bounds();
    // One sheet of at most a centimetre, a steel frame at most 2 mm proud of it: nothing to see.
    EXPECT_LT(box.sizes().z(), 0.0125f) << i;
    int heat = 0, toggles = 0;
    for (const GroundTruthPoint& p : hob.points) {
      EXPECT_NEAR(p.position.z(), box.max().z(), 0.0022f);
      (p.type == "heatsource" ? heat : toggles) += 1;
      // Something is printed there: a zone's ring (its centre may carry a dot or nothing) or a
      // symbol.
      if (p.type == "togglebutton") EXPECT_GT(brightestNear(hob, p.position, 0.01f), 0.3f) << i;
    }
    EXPECT_EQ(heat, hob.generator.at("burners").get<int>());
    EXPECT_EQ(toggles, hob.generator.at("knobs").get<int>());
    EXPECT_GE(toggles, 2);
    // Controls do not sit on a zone: at least a centimetre beyond every zone centre's
    // neighbourhood.
    for (const GroundTruthPoint& t : hob.points) {
      if (t.type != "togglebutton") continue;
      for (const GroundTruthPoint& h : hob.points)
        if (h.type == "heatsource") EXPECT_GT((t.position - h.position).norm(), 0.04f) << i;
    }
    std::vector<float> ys;
    for (const GroundTruthPoint& t : hob.points)
      if (t.type == "togglebutton") ys.push_back(t.position.y());
    if (std::adjacent_find(ys.begin(), ys.end(),
                           [](float a, float b) { return std::abs(a - b) > 1e-4f; }) != ys.end())
      ++withCluster;
  }
  EXPECT_GT(withCluster, 0) << "no control cluster in more than one row";
}

TEST(GlassHobs, TheShareIsHonouredAndABadShareIsRefused) {
  int slabs = 0;
  for (int i = 0; i < 200; ++i)
    slabs += makeRawObject("stove", 43, i, GeneratorOptions{0.0, 0.5}).generator.at("kind") ==
             "glass_slab";
  EXPECT_NEAR(slabs / 200.0, 0.5, 0.1);
  EXPECT_EQ(makeRawObject("sink", 43, 0, kAllGlassHobs).mesh.triangles.size(),
            makeRawObject("sink", 43, 0).mesh.triangles.size());
  EXPECT_THROW(makeRawObject("stove", 43, 0, GeneratorOptions{0.0, 1.5}), InvalidArgument);
  EXPECT_THROW(makeRawObject("stove", 43, 0, GeneratorOptions{0.0, -0.1}), InvalidArgument);
}

}  // namespace
}  // namespace sagrid::gen
