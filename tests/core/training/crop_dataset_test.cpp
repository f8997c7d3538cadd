#include "core/training/crop_dataset.h"

#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/dataset/dataset.h"
#include "core/generate/dataset_generator.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;

struct Loaded {
  ObjectLabels labels;
  Mesh mesh;
};

Loaded load(const DatasetEntry& entry) {
  Loaded l;
  l.labels = readLabels(entry.labels);
  l.mesh = importMesh(entry.mesh, ImportOptions(upAxisOrZ(l.labels.object.up)));
  return l;
}

TEST(CropDataset, EachCropHoldsItsTypesPointsWhereTheObjectHasThem) {
  const fs::path data = test::freshTempDir("crop-src"), out = test::freshTempDir("crop-out");
  gen::generateDataset({{"sink", 8, 61}}, gen::MeshFormat::Mixed,
                       data);  // y-up GLB and z-up OBJ, random units
  const CropDatasetSummary summary = writeCropDataset(data, out);
  EXPECT_EQ(summary.objects, 8);
  ASSERT_GT(summary.crops, 8);
  const auto crops = readDataset(out);
  ASSERT_EQ(static_cast<int>(crops.size()), summary.crops);
  std::map<std::string, DatasetEntry> sources;
  for (const auto& e : readDataset(data)) sources[e.id] = e;
  for (const auto& entry : crops) {
    const Loaded crop = load(entry);
    const std::string id = crop.labels.object.extra.at("crop_of").at("id");
    const std::string type = crop.labels.object.extra.at("crop_of").at("type");
    const Loaded object = load(sources.at(id));
    EXPECT_EQ(crop.labels.object.category, "sink");
    EXPECT_EQ(crop.labels.object.extra.at("meters_per_unit"),
              object.labels.object.extra.at("meters_per_unit"));
    // A part of the object, in its units and frame: inside its bounds, fewer triangles.
    const float extent = object.mesh.bounds().sizes().maxCoeff();
    Eigen::AlignedBox3f grown = object.mesh.bounds();
    grown.min().array() -= 1e-4f * extent;
    grown.max().array() += 1e-4f * extent;
    EXPECT_TRUE(grown.contains(crop.mesh.bounds())) << entry.id;
    EXPECT_LT(crop.mesh.bounds().sizes().maxCoeff(), 0.6f * extent + 1e-4f * extent) << entry.id;
    // Every point of the crop's type is kept, and each kept point is one of the object's.
    const UpAxis up = upAxisOrZ(object.labels.object.up);
    EXPECT_EQ(crop.labels.ofType(type).size(), object.labels.ofType(type).size()) << entry.id;
    for (const auto& p : crop.labels.affordances) {
      float nearest = 1e30f;
      for (const auto& q : object.labels.affordances)
        if (q.type == p.type)
          nearest = std::min(nearest, (fileToZUp(q.position, up) - p.position).norm());
      EXPECT_LT(nearest, 1e-5f * extent) << entry.id;
      EXPECT_TRUE(grown.contains(p.position));
    }
  }
}

TEST(CropDataset, TheSameSeedWritesTheSameCropsAndAnEmptyFolderIsAnError) {
  const fs::path data = test::freshTempDir("crop-seed-src");
  gen::generateDataset({{"sink", 3, 62}}, gen::MeshFormat::Obj, data);
  const fs::path a = test::freshTempDir("crop-a"), b = test::freshTempDir("crop-b"),
                 c = test::freshTempDir("crop-c");
  writeCropDataset(data, a);
  writeCropDataset(data, b);
  CropDatasetOptions other;
  other.seed = 2;
  writeCropDataset(data, c, other);
  const auto first = readDataset(a);
  ASSERT_FALSE(first.empty());
  const std::string bytes = readFileBytes(first.front().mesh);
  EXPECT_EQ(bytes, readFileBytes(b / fs::relative(first.front().mesh, a)));
  EXPECT_NE(bytes, readFileBytes(c / fs::relative(first.front().mesh, a)));
  EXPECT_THROW(
      writeCropDataset(test::freshTempDir("crop-empty"), test::freshTempDir("crop-empty-out")),
      FileError);
}

}  // namespace
}  // namespace sagrid
