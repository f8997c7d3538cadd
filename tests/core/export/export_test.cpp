// Simulator exports and "Add to training set" on a tiny OBJ with known points: names, frames
// (y-up files stood up, units scaled to metres), files written, manifest updated in place.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/export/export_objects.h"
#include "core/export/mjcf_export.h"
#include "core/export/omnigibson_export.h"
#include "core/export/training_set.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;

fs::path writeObject(const fs::path& dir, const std::string& up = "z", double metersPerUnit = 1.0) {
  fs::create_directories(dir);
  std::ofstream(dir / "mesh.obj")
      << "mtllib mesh.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
  std::ofstream(dir / "mesh.mtl") << "newmtl red\nKd 1 0 0\nmap_Kd tex.png\n";
  std::ofstream(dir / "tex.png") << "not really a png";
  ObjectLabels labels;
  labels.object.id = "my_stove_01";
  labels.object.mesh = "mesh.obj";
  labels.object.category = "stove";
  labels.object.up = up;
  if (metersPerUnit != 1.0) labels.object.extra["meters_per_unit"] = metersPerUnit;
  AffordancePoint heat;
  heat.type = "heatsource";
  heat.position = {1, 2, 3};
  AffordancePoint heat2 = heat;
  heat2.position = {4, 5, 6};
  AffordancePoint toggle;
  toggle.type = "togglebutton";
  toggle.position = {0.5f, 0.25f, 0.125f};
  labels.affordances = {heat, heat2, toggle};
  writeLabels(dir / "labels.json", labels);
  return dir / "labels.json";
}

TEST(OmniGibsonExport, MetaLinksNamedAndPlaced) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = writeObject(dir / "in");
  const auto result =
      exportOmniGibson(readLabels(labelsPath), dir / "in" / "mesh.obj", dir / "out");
  EXPECT_EQ(result.root, dir / "out" / "mystove01");  // ids lose their underscores
  const std::string urdf = readFileBytes(result.mainFile);
  EXPECT_NE(urdf.find("name=\"meta__base_link_heatsource_0_0_link\""), std::string::npos);
  EXPECT_NE(urdf.find("name=\"meta__base_link_heatsource_1_0_link\""), std::string::npos);
  EXPECT_NE(urdf.find("name=\"meta__base_link_togglebutton_0_0_link\""), std::string::npos);
  EXPECT_NE(urdf.find("<origin xyz=\"4 5 6\""), std::string::npos);
  EXPECT_NE(urdf.find("<sphere radius="), std::string::npos);  // the toggle button's volume
  const auto meta = nlohmann::json::parse(readFileBytes(result.root / "misc" / "metadata.json"));
  const auto& heat = meta.at("meta_links").at("base_link").at("heatsource");
  EXPECT_EQ(heat.at("1").at(0).at("type"), "point");
  EXPECT_DOUBLE_EQ(heat.at("1").at(0).at("position").at(2).get<double>(), 6.0);
  EXPECT_EQ(meta["meta_links"]["base_link"]["togglebutton"]["0"][0]["type"], "sphere");
  EXPECT_TRUE(fs::exists(result.root / "shape" / "visual" / "mesh.obj"));
  EXPECT_TRUE(fs::exists(result.root / "shape" / "visual" / "mesh.mtl"));
  EXPECT_TRUE(fs::exists(result.root / "shape" / "visual" / "tex.png"));
  // No link name part may carry an underscore of its own: split on "_" gives a fixed shape.
  std::regex link("meta__base_link_([a-z0-9]+)_([0-9]+)_0_link");
  EXPECT_TRUE(std::regex_search(urdf, link));
}

TEST(OmniGibsonExport, YUpCentimetreFileBecomesZUpMetres) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = writeObject(dir / "in", "y", 0.01);
  const auto result =
      exportOmniGibson(readLabels(labelsPath), dir / "in" / "mesh.obj", dir / "out");
  const auto meta = nlohmann::json::parse(readFileBytes(result.root / "misc" / "metadata.json"));
  const auto p = meta["meta_links"]["base_link"]["heatsource"]["0"][0]["position"];
  // (1, 2, 3) y-up cm -> (1, -3, 2) z-up -> metres.
  EXPECT_NEAR(p[0].get<double>(), 0.01, 1e-7);
  EXPECT_NEAR(p[1].get<double>(), -0.03, 1e-7);
  EXPECT_NEAR(p[2].get<double>(), 0.02, 1e-7);
  EXPECT_NE(readFileBytes(result.mainFile).find("rpy=\"1.5707963 0 0\""), std::string::npos);
}

TEST(MjcfExport, SitesNamedByTypeAndIndex) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = writeObject(dir / "in");
  const auto result = exportMjcf(readLabels(labelsPath), dir / "in" / "mesh.obj", dir / "out");
  const std::string xml = readFileBytes(result.mainFile);
  EXPECT_NE(xml.find("<site name=\"heatsource_0\" type=\"sphere\" pos=\"1 2 3\""),
            std::string::npos);
  EXPECT_NE(xml.find("<site name=\"heatsource_1\" type=\"sphere\" pos=\"4 5 6\""),
            std::string::npos);
  EXPECT_NE(xml.find("<site name=\"togglebutton_0\""), std::string::npos);
  EXPECT_NE(xml.find("file=\"mesh.obj\""), std::string::npos);
  EXPECT_TRUE(result.warnings.empty());
}

TEST(ExportObjects, FolderOfObjectsAndBadFormat) {
  const auto dir = test::freshTempDir();
  writeObject(dir / "data" / "a");
  writeObject(dir / "data" / "b");
  const auto results = exportObjects(dir / "data", "mjcf", dir / "out");
  EXPECT_EQ(results.size(), 2u);
  EXPECT_THROW(exportObjects(dir / "data", "usd", dir / "out"), InvalidArgument);
  EXPECT_THROW(exportObjects(dir / "missing", "mjcf", dir / "out"), FileError);
}

TEST(ExportCli, WritesOneFilePerObject) {
  const auto dir = test::freshTempDir();
  writeObject(dir / "obj");
  const auto r =
      test::runSagrid("export " + test::shellQuote((dir / "obj" / "labels.json").string()) +
                      " --format omnigibson --out " + test::shellQuote((dir / "out").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "mystove01" / "urdf" / "mystove01.urdf"));
  const auto bad =
      test::runSagrid("export " + test::shellQuote((dir / "nothing").string()) +
                      " --format mjcf --out " + test::shellQuote((dir / "out").string()));
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find("sagrid: error:"), std::string::npos);
}

TEST(TrainingSet, CopiesWithProvenanceAndReplacesManifestLine) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = writeObject(dir / "in");
  const ObjectLabels labels = readLabels(labelsPath);
  const auto entry = addToTrainingSet(labels, dir / "in" / "mesh.obj", labelsPath, dir / "set");
  EXPECT_EQ(entry.id, "my_stove_01");
  EXPECT_TRUE(fs::exists(dir / "set" / "my_stove_01" / "mesh.obj"));
  EXPECT_TRUE(fs::exists(dir / "set" / "my_stove_01" / "mesh.mtl"));
  const ObjectLabels copied = readLabels(entry.labels);
  EXPECT_EQ(copied.affordances.size(), 3u);
  EXPECT_EQ(copied.object.mesh, "mesh.obj");
  ASSERT_TRUE(copied.extra.contains("provenance"));
  EXPECT_NE(copied.extra["provenance"]["mesh"].get<std::string>().find("in/mesh.obj"),
            std::string::npos);
  addToTrainingSet(labels, dir / "in" / "mesh.obj", labelsPath, dir / "set");  // again: replaced
  const std::string manifest = readFileBytes(dir / "set" / "manifest.jsonl");
  EXPECT_EQ(std::count(manifest.begin(), manifest.end(), '\n'), 1);
  const auto line = nlohmann::json::parse(manifest.substr(0, manifest.find('\n')));
  EXPECT_EQ(line["id"], "my_stove_01");
  EXPECT_EQ(line["category"], "stove");
  EXPECT_EQ(line["mesh"], "my_stove_01/mesh.obj");
  EXPECT_EQ(line["labels"], "my_stove_01/labels.json");
}

TEST(TrainingSet, RefusesObjectsWithoutCategory) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = writeObject(dir / "in");
  ObjectLabels labels = readLabels(labelsPath);
  labels.object.category.clear();
  EXPECT_THROW(addToTrainingSet(labels, dir / "in" / "mesh.obj", labelsPath, dir / "set"),
               InvalidArgument);
  EXPECT_FALSE(fs::exists(dir / "set" / "manifest.jsonl"));
}

}  // namespace
}  // namespace sagrid
