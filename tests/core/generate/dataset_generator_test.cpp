#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/dataset/dataset.h"
#include "core/generate/dataset_generator.h"
#include "core/generate/dataset_stats.h"
#include "core/geometry/closest_point_on_triangle.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"
#include "support/analytic_meshes.h"
#include "support/test_paths.h"

namespace sagrid::gen {
namespace {

using test::bruteForceDistance;

namespace fs = std::filesystem;

std::map<std::string, std::string> allFiles(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = readFileBytes(e.path());
  }
  return files;
}

TEST(DatasetGenerator, SameSeedGivesByteIdenticalFiles) {
  const fs::path a = test::freshTempDir("a"), b = test::freshTempDir("b");
  generateDataset({{"stove", 4, 77}, {"sink", 4, 78}}, MeshFormat::Mixed, a);
  generateDataset({{"stove", 4, 77}, {"sink", 4, 78}}, MeshFormat::Mixed, b);
  const auto fa = allFiles(a), fb = allFiles(b);
  ASSERT_GE(fa.size(), 8u * 2 + 1);
  EXPECT_EQ(fa, fb);
  // A different seed changes the objects.
  const fs::path c = test::freshTempDir("c");
  generateDataset({{"stove", 4, 79}, {"sink", 4, 78}}, MeshFormat::Mixed, c);
  EXPECT_NE(allFiles(c), fa);
}

TEST(DatasetGenerator, WritesManifestLabelsAndMeshesThatLoadBack) {
  const fs::path dir = test::freshTempDir();
  const auto lines = generateDataset({{"stove", 6, 5}, {"sink", 6, 6}}, MeshFormat::Mixed, dir);
  ASSERT_EQ(lines.size(), 12u);
  const auto entries = readDataset(dir);
  ASSERT_EQ(entries.size(), 12u);
  int glb = 0;
  for (const auto& entry : entries) {
    const ObjectLabels labels = readLabels(entry.labels);
    EXPECT_EQ(labels.object.category, entry.category);
    EXPECT_EQ(labels.object.sha256, sha256Hex(readFileBytes(entry.mesh)));
    const Mesh mesh = importMesh(entry.mesh);
    glb += entry.mesh.extension() == ".glb";
    EXPECT_EQ(labels.object.up, mesh.fileUp == UpAxis::Y ? "y" : "z");
    EXPECT_GT(mesh.triangleCount(), 100u);
    // Ground truth is on the surface of the mesh as a third party loads it.
    const double mpu = labels.object.extra["meters_per_unit"].get<double>();
    for (const auto& a : labels.affordances) {
      const float d = bruteForceDistance(mesh, fileToZUp(a.position, mesh.fileUp));
      EXPECT_LE(d * mpu, 0.01) << entry.id << " " << a.type;
    }
  }
  EXPECT_GT(glb, 0);
  EXPECT_LT(glb, 12);
}

TEST(DatasetGenerator, LongerRunExtendsShorterRun) {
  const FinishedObject a = makeObject("sink", 3, 2, MeshFormat::Obj);
  const FinishedObject b = makeObject("sink", 3, 2, MeshFormat::Obj);
  EXPECT_EQ(a.id, "sink_s3_00002");
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  EXPECT_EQ(toJson(a.labels), toJson(b.labels));
}

TEST(DatasetGenerator, StatsTableCountsGeneratorParameters) {
  const fs::path dir = test::freshTempDir();
  generateDataset({{"stove", 5, 1}, {"sink", 5, 1}}, MeshFormat::Obj, dir);
  const std::string table = datasetStatsTable(dir);
  EXPECT_NE(table.find("## stove (5 objects)"), std::string::npos);
  EXPECT_NE(table.find("## sink (5 objects)"), std::string::npos);
  EXPECT_NE(table.find("| burner_look | count |"), std::string::npos);
  EXPECT_NE(table.find("| faucet | count |"), std::string::npos);
  EXPECT_NE(table.find("| .obj | 5 |"), std::string::npos);
}

TEST(DatasetGenerator, RejectsUnknownCategoryAndFormat) {
  EXPECT_THROW(generateDataset({{"oven", 1, 1}}, MeshFormat::Obj, test::freshTempDir()), InvalidArgument);
  EXPECT_THROW(parseMeshFormat("fbx"), InvalidArgument);
}

TEST(DatasetGenerator, BenchPresetHasFixedCounts) {
  int train = 0, val = 0;
  for (const auto& split : benchPreset()) {
    for (const auto& r : split.requests) (split.name == "train" ? train : val) += r.count;
  }
  EXPECT_EQ(train, 400);
  EXPECT_EQ(val, 100);
}

// The point decision learns from generated objects whose fields read as on objects nobody trained
// on: no request of the decision preset draws the objects of a split a network trains on or is
// judged on (the same category and seed), and it has stoves, sinks and glass hobs.
TEST(DatasetGenerator, DecisionPresetDrawsObjectsNoOtherPresetHas) {
  std::set<std::pair<std::string, std::uint64_t>> others;
  for (const auto* preset : {&benchPreset(), &wallFixturePreset(), &glassHobPreset()})
    for (const auto& split : *preset)
      for (const auto& r : split.requests) others.insert({r.category, r.seed});
  int stoves = 0, sinks = 0, glassHobs = 0;
  for (const auto& split : decisionPreset())
    for (const auto& r : split.requests) {
      EXPECT_EQ(others.count({r.category, r.seed}), 0u) << r.category << " seed " << r.seed;
      (r.category == "sink" ? sinks : stoves) += r.count;
      if (r.options.glassSlabHobs > 0) glassHobs += r.count;
    }
  EXPECT_EQ(stoves, 80);
  EXPECT_EQ(sinks, 40);
  EXPECT_EQ(glassHobs, 40);
}

}  // namespace
}  // namespace sagrid::gen
