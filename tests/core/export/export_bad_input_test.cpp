// Bad input to the simulator exports (issue 12 "Bad input", issue 14 numbers): every problem is
// one clear error naming the file and field, or a warning with valid output; never a
// half-written folder, never inf/nan/null in a file.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/export/export_objects.h"
#include "core/export/mjcf_export.h"
#include "core/export/omnigibson_export.h"
#include "core/export/omnigibson_model_name.h"
#include "core/export/stl_file.h"
#include "support/analytic_meshes.h"
#include "support/folder_listing.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

ExportOptions fast() {
  ExportOptions options;
  options.collision = CollisionMode::Hull;
  return options;
}

void expectFileError(const std::function<void()>& run, const fs::path& file,
                     const std::string& mentions) {
  try {
    run();
    ADD_FAILURE() << "no error; expected one naming " << file;
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string(), 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find(mentions), std::string::npos) << e.what();
  }
}

fs::path stoveWith(const fs::path& dir, const std::function<void(json&)>& edit) {
  const fs::path labels = test::writeAnalyticStove(dir);
  json j = json::parse(readFileBytes(labels));
  edit(j);
  writeFileAtomic(labels, j.dump());
  return labels;
}

TEST(ExportBadInput, MetersPerUnitOutsideSaneRangeNamesTheFile) {
  const auto dir = test::freshTempDir();
  int i = 0;
  for (const json& value :
       {json(0), json(-1), json(1e308), json(1e-300), json("abc"), json(true)}) {
    SCOPED_TRACE(value.dump());
    const auto labels = stoveWith(dir / ("in" + std::to_string(i++)),
                                  [&](json& j) { j["object"]["meters_per_unit"] = value; });
    for (const char* format : {"mjcf", "omnigibson"}) {
      expectFileError([&] { exportObjects(labels, format, dir / "out", fast()); }, labels,
                      "meters_per_unit");
    }
  }
  EXPECT_TRUE(test::entriesBelow(dir / "out").empty());
}

TEST(ExportBadInput, UnknownUnitsWarnThatMetresAreAssumed) {
  const auto dir = test::freshTempDir();
  const auto none = stoveWith(dir / "none", [](json& j) { j["object"].erase("units"); });
  const auto odd = stoveWith(dir / "odd", [](json& j) { j["object"]["units"] = "furlong"; });
  for (const auto& labels : {none, odd}) {
    const auto results = exportObjects(labels, "mjcf", dir / "out", fast());
    ASSERT_EQ(results.size(), 1u);
    ASSERT_FALSE(results[0].warnings.empty());
    EXPECT_NE(results[0].warnings[0].find("metres assumed"), std::string::npos);
    EXPECT_EQ(results[0].warnings[0].rfind(labels.string(), 0), 0u);
  }
  const auto notText = stoveWith(dir / "bad", [](json& j) { j["object"]["units"] = 3; });
  expectFileError([&] { exportObjects(notText, "mjcf", dir / "out2", fast()); }, notText, "units");
}

TEST(ExportBadInput, PositionsAndMassMustBeUsableNumbers) {
  const auto dir = test::freshTempDir();
  const auto far = stoveWith(dir / "far", [](json& j) {
    j["affordances"][0]["position"] = {1e20, 0, 0};
  });
  expectFileError([&] { exportObjects(far, "omnigibson", dir / "out", fast()); }, far,
                  "affordances[0].position");
  ObjectLabels labels = readLabels(test::writeAnalyticStove(dir / "nan"));
  labels.affordances[1].position.x() = std::numeric_limits<float>::quiet_NaN();
  expectFileError(
      [&] {
        exportMjcf(labels, dir / "nan" / "mesh.obj", dir / "out", fast(),
                   dir / "nan" / "labels.json");
      },
      dir / "nan" / "labels.json", "affordances[1].position");
  int i = 0;
  for (const json& mass : {json(-3), json(0), json("heavy"), json(1e308)}) {
    const auto labelsPath = stoveWith(dir / ("mass" + std::to_string(i++)),
                                      [&](json& j) { j["object"]["mass_kg"] = mass; });
    expectFileError([&] { exportObjects(labelsPath, "mjcf", dir / "out", fast()); }, labelsPath,
                    "mass_kg");
  }
  EXPECT_TRUE(test::entriesBelow(dir / "out").empty());
}

TEST(ExportBadInput, MeshesTheImporterRefusesLeaveNothing) {
  const auto dir = test::freshTempDir();
  const auto labels = test::writeAnalyticStove(dir / "in");
  std::ofstream(dir / "in" / "mesh.obj", std::ios::trunc) << "this is not a mesh\n";
  for (const char* format : {"mjcf", "omnigibson"}) {
    expectFileError([&] { exportObjects(labels, format, dir / "out", fast()); },
                    dir / "in" / "mesh.obj", "");
  }
  EXPECT_TRUE(test::entriesBelow(dir / "out").empty());
}

TEST(ExportBadInput, AFifoAsMeshIsRefusedWithoutBlocking) {
  const auto dir = test::freshTempDir();
  const auto labels = test::writeAnalyticStove(dir / "in");
  fs::remove(dir / "in" / "mesh.obj");
  if (::mkfifo((dir / "in" / "mesh.obj").c_str(), 0600) != 0) GTEST_SKIP() << "no FIFOs here";
  expectFileError([&] { exportObjects(labels, "mjcf", dir / "out", fast()); },
                  dir / "in" / "mesh.obj", "not a regular file");
}

TEST(ExportBadInput, FailedReexportKeepsThePreviousExportWhole) {
  const auto dir = test::freshTempDir();
  const auto labels = test::writeAnalyticStove(dir / "in");
  const auto first = exportObjects(labels, "mjcf", dir / "out", fast());
  const auto before = test::entriesBelow(dir / "out");
  const std::string xml = readFileBytes(first[0].mainFile);
  stoveWith(dir / "in", [](json& j) { j["object"]["meters_per_unit"] = -1; });
  EXPECT_THROW(exportObjects(labels, "mjcf", dir / "out", fast()), FileError);
  EXPECT_EQ(test::entriesBelow(dir / "out"), before);  // no .partial folder, nothing replaced
  EXPECT_EQ(readFileBytes(first[0].mainFile), xml);
}

// kill -9 in the middle of an export leaves only a hidden staging folder; the next export of the
// same object removes it (its process is gone) and leaves no debris.
TEST(ExportBadInput, RerunRemovesTheLeftoversOfAKilledExport) {
  const auto dir = test::freshTempDir();
  const auto labels = test::writeAnalyticStove(dir / "in");
  const fs::path stale = dir / "out" / ".my_stove_01.partial-2147483647-0";  // no such process
  fs::create_directories(stale / "meshes");
  std::ofstream(stale / "meshes" / "visual_0.stl") << "half";
  const auto results = exportObjects(labels, "mjcf", dir / "out", fast());
  EXPECT_FALSE(fs::exists(stale));
  std::vector<fs::path> top;
  for (const auto& item : fs::directory_iterator(dir / "out")) top.push_back(item.path());
  EXPECT_EQ(top, std::vector<fs::path>{results[0].root});
}

// Numbers in labels that overflow or are absurd never reach a file: an error names labels.json.
TEST(ExportBadInput, OverflowingLabelNumbersNameTheLabelsFile) {
  const auto dir = test::freshTempDir();
  int i = 0;
  for (const json position : {json({1e39, 0, 0}), json({-1e308, 0, 0}), json({0, 1e300, 0})}) {
    const auto labels = stoveWith(dir / ("in" + std::to_string(i++)),
                                  [&](json& j) { j["affordances"][0]["position"] = position; });
    for (const char* format : {"mjcf", "omnigibson"})
      expectFileError([&] { exportObjects(labels, format, dir / "out", fast()); }, labels, "");
  }
  EXPECT_TRUE(test::entriesBelow(dir / "out").empty());
}

// Open, non-manifold and zero-volume meshes export with valid output (and warnings).
TEST(ExportBadInput, OpenNonManifoldAndFlatMeshesGiveValidOutput) {
  Mesh open = test::box({0, 0, 0}, {0.4f, 0.4f, 0.2f});
  open.triangles.erase(open.triangles.begin() + 4, open.triangles.begin() + 6);  // a face gone
  Mesh nonManifold = test::box({0, 0, 0}, {0.2f, 0.2f, 0.2f});
  test::append(nonManifold, test::box({0.2f, 0.2f, 0}, {0.4f, 0.4f, 0.2f}));  // shares an edge
  nonManifold.positions.push_back({0.1f, 0.1f, 0.2f});
  nonManifold.positions.push_back({0.1f, 0.1f, 0.4f});
  nonManifold.normals.resize(nonManifold.positions.size(), Eigen::Vector3f::UnitX());
  nonManifold.triangles.push_back({2, static_cast<int>(nonManifold.positions.size()) - 2,
                                   static_cast<int>(nonManifold.positions.size()) - 1});  // a fin
  const Mesh flat = test::quadZ({0, 0}, {0.4f, 0.3f}, 0.0f);
  const auto dir = test::freshTempDir();
  int i = 0;
  for (const Mesh* mesh : std::vector<const Mesh*>{&open, &nonManifold, &flat}) {
    SCOPED_TRACE(i);
    const fs::path in = dir / ("in" + std::to_string(i++));
    const auto labels = test::writeLabelledObject(
        in, *mesh, {test::affordance("heatsource", {0.1f, 0.1f, 0.2f})}, "odd", "stove");
    for (const char* format : {"mjcf", "omnigibson"}) {
      ExportOptions options;  // the decomposition for MJCF, one hull for OmniGibson: both paths
      options.collision =
          std::string(format) == "mjcf" ? CollisionMode::Decompose : CollisionMode::Hull;
      options.maxCollisionParts = 8;
      const auto results = exportObjects(labels, format, dir / format, options);
      ASSERT_EQ(results.size(), 1u);
      EXPECT_GT(results[0].massKg, 0.0);
      EXPECT_GE(results[0].collisionParts, 1);
      EXPECT_EQ(results[0].visualTriangles, static_cast<int>(mesh->triangles.size()));
      for (const auto& file : test::entriesBelow(results[0].root)) {
        if (!fs::is_regular_file(file) || file.extension() == ".stl") continue;
        const std::string text = readFileBytes(file);
        for (const char* bad : {"nan", "inf", "null"})
          EXPECT_EQ(text.find(bad), std::string::npos) << file << " holds " << bad;
      }
    }
  }
}

TEST(ExportBadInput, IdsWithoutSixLettersStillGiveValidModelNames) {
  std::vector<std::string> warnings;
  exportdetail::OmniGibsonModelNames names;
  const std::string digits = names.claim("1234", warnings);
  EXPECT_TRUE(exportdetail::isOmniGibsonModelName(digits)) << digits;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("'1234'"), std::string::npos);
  const std::string short_ = names.claim("ab_9", warnings);
  EXPECT_EQ(short_.substr(0, 2), "ab");
  EXPECT_TRUE(exportdetail::isOmniGibsonModelName(short_));
  const std::string markup = names.claim("<\">&'", warnings);
  EXPECT_TRUE(exportdetail::isOmniGibsonModelName(markup));
  // Deterministic: another export names the same ids the same way.
  exportdetail::OmniGibsonModelNames again;
  std::vector<std::string> ignored;
  EXPECT_EQ(again.claim("1234", ignored), digits);
  // Collision-free within one export.
  exportdetail::OmniGibsonModelNames one;
  const std::string a = one.claim("flat_stove_1", ignored);
  const std::string b = one.claim("flat_stove_2", ignored);
  const std::string c = one.claim("flat_stove_3", ignored);
  EXPECT_EQ(a, "flatst");
  EXPECT_NE(a, b);
  EXPECT_NE(b, c);
  EXPECT_NE(a, c);
  for (const auto& n : {a, b, c}) EXPECT_TRUE(exportdetail::isOmniGibsonModelName(n)) << n;
}

// A million triangles: the export finishes (bounded work: the decomposition and the mass run on a
// fixed voxel grid) and reports its progress through every stage.
TEST(ExportBadInput, MillionTriangleMeshExportsWithProgressSlow) {
  const auto dir = test::freshTempDir();
  fs::create_directories(dir / "in");
  const Mesh sphere = test::uvSphere({0, 0, 0.3f}, 0.3f, 501);
  ASSERT_GE(sphere.triangles.size(), 1000000u);
  writeFileAtomic(dir / "in" / "mesh.stl", exportdetail::encodeBinaryStl(sphere));
  ObjectLabels labels;
  labels.object.id = "ball";
  labels.object.mesh = "mesh.stl";
  labels.object.extra["units"] = "m";
  labels.affordances = {test::affordance("togglebutton", {0, 0, 0.6f})};
  writeLabels(dir / "in" / "labels.json", labels);
  ExportOptions options;
  std::vector<std::pair<float, std::string>> progress;
  options.progress = [&](float f, const std::string& stage) { progress.emplace_back(f, stage); };
  const auto results = exportObjects(dir / "in" / "labels.json", "mjcf", dir / "out", options);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_GE(results[0].visualTriangles, 1000000);
  ASSERT_GE(progress.size(), 3u);
  EXPECT_EQ(progress.front().second, "importing");
  EXPECT_FLOAT_EQ(progress.back().first, 1.0f);
  for (std::size_t i = 1; i < progress.size(); ++i)
    EXPECT_GE(progress[i].first, progress[i - 1].first) << progress[i].second;
}

}  // namespace
}  // namespace sagrid
