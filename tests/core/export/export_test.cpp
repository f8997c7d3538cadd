// Simulator exports and "Add to training set" on small analytic objects with known points: layout
// and names, sites, parts, collision modes, mass, frames (y-up files stood up, units scaled to
// metres), batch naming, the CLI, and the training-set manifest.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/dataset/object_source.h"
#include "core/export/export_objects.h"
#include "core/export/mjcf_export.h"
#include "core/export/omnigibson_export.h"
#include "core/export/training_set.h"
#include "support/analytic_meshes.h"
#include "support/labelled_objects.h"
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

std::string urdfOf(const SimulatorExport& r, const std::string& suffix = "") {
  return readFileBytes(r.mainFile.parent_path() / (r.mainFile.stem().string() + suffix + ".urdf"));
}

TEST(OmniGibsonExport, LayoutModelNameAndMetaLinks) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = test::writeAnalyticStove(dir / "in");
  const auto result = exportOmniGibson(readLabels(labelsPath), dir / "in" / "mesh.obj", dir / "out",
                                       {}, labelsPath);
  EXPECT_EQ(result.root, dir / "out" / "stove" / "mystov");  // <category>/<6 letters>
  EXPECT_EQ(result.mainFile, result.root / "urdf" / "mystov.urdf");
  EXPECT_TRUE(fs::exists(result.root / "shape" / "visual" / "mystov_base_link_visual.obj"));
  EXPECT_TRUE(fs::exists(result.root / "shape" / "visual" / "mystov_base_link_visual.mtl"));
  EXPECT_GE(result.collisionParts, 1);
  EXPECT_TRUE(fs::exists(result.root / "shape" / "collision" / "mystov_base_link_collision_0.obj"));
  const std::string urdf = urdfOf(result);
  EXPECT_EQ(urdf.find("meta__"), std::string::npos);  // the importer adds them from metadata
  EXPECT_NE(urdf.find("<collision name=\"base_link_collision_0\">"), std::string::npos);
  EXPECT_NE(urdf.find("<inertial>"), std::string::npos);
  const std::string withMeta = urdfOf(result, "_with_meta_links");
  EXPECT_NE(withMeta.find("<link name=\"meta__base_link_heatsource_3_0_link\">"),
            std::string::npos);
  EXPECT_NE(withMeta.find("<joint name=\"meta__base_link_togglebutton_0_0_joint\" "
                          "type=\"fixed\">"),
            std::string::npos);
  const auto meta = nlohmann::json::parse(readFileBytes(result.root / "misc" / "metadata.json"));
  EXPECT_NEAR(meta["bbox_size"][1].get<double>(), 0.52, 1e-5);  // knobs stick out 2 cm
  EXPECT_NEAR(meta["base_link_offset"][1].get<double>(), -0.01, 1e-5);
  EXPECT_TRUE(meta["link_tags"].is_object());
  const auto& heat = meta["meta_links"]["base_link"]["heatsource"];
  ASSERT_EQ(heat.size(), 4u);
  EXPECT_NEAR(heat["1"][0]["position"][1].get<double>(), 0.1, 1e-6);
  EXPECT_EQ(heat["1"][0]["orientation"], nlohmann::json({0.0, 0.0, 0.0, 1.0}));
  const auto& knob = meta["meta_links"]["base_link"]["togglebutton"]["2"][0];
  EXPECT_EQ(knob["type"], "sphere");
  EXPECT_GT(knob["size"][0].get<double>(), 0.0);
  EXPECT_GT(meta["sagrid"]["mass_kg"].get<double>(), 0.0);
}

TEST(OmniGibsonExport, FluidSourceIsParticleSourceOrLegacy) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = test::writeLabelledObject(
      dir / "in", test::box({0, 0, 0}, {0.5f, 0.4f, 0.3f}),
      {test::affordance("fluidsource", {0.25f, 0.1f, 0.5f})}, "basin", "sink");
  const ObjectLabels labels = readLabels(labelsPath);
  ExportOptions options;
  options.collision = CollisionMode::Hull;
  auto r = exportOmniGibson(labels, dir / "in" / "mesh.obj", dir / "out", options, labelsPath);
  auto meta = nlohmann::json::parse(readFileBytes(r.root / "misc" / "metadata.json"));
  const auto& source = meta["meta_links"]["base_link"]["particlesource"]["0"][0];
  EXPECT_EQ(source["type"], "cylinder");
  EXPECT_EQ(source["size"], nlohmann::json({0.0125, 0.0125, 0.05}));
  EXPECT_EQ(r.collisionParts, 1);
  options.legacyFluidSource = true;
  r = exportOmniGibson(labels, dir / "in" / "mesh.obj", dir / "out", options, labelsPath);
  meta = nlohmann::json::parse(readFileBytes(r.root / "misc" / "metadata.json"));
  EXPECT_TRUE(meta["meta_links"]["base_link"].contains("fluidsource"));
  EXPECT_FALSE(meta["meta_links"]["base_link"].contains("particlesource"));
}

TEST(OmniGibsonExport, YUpCentimetreFileBecomesZUpMetres) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = writeObject(dir / "in", "y", 0.01);
  ExportOptions options;
  options.collision = CollisionMode::None;
  const auto result = exportOmniGibson(readLabels(labelsPath), dir / "in" / "mesh.obj", dir / "out",
                                       options, labelsPath);
  const auto meta = nlohmann::json::parse(readFileBytes(result.root / "misc" / "metadata.json"));
  const auto p = meta["meta_links"]["base_link"]["heatsource"]["0"][0]["position"];
  // (1, 2, 3) y-up cm -> (1, -3, 2) z-up -> metres.
  EXPECT_NEAR(p[0].get<double>(), 0.01, 1e-7);
  EXPECT_NEAR(p[1].get<double>(), -0.03, 1e-7);
  EXPECT_NEAR(p[2].get<double>(), 0.02, 1e-7);
  // The mesh (a 1 x 1 triangle in x/y of the y-up file) is stood up and scaled: 1 cm along x, z.
  EXPECT_NEAR(meta["bbox_size"][0].get<double>(), 0.01, 1e-6);
  EXPECT_NEAR(meta["bbox_size"][2].get<double>(), 0.01, 1e-6);
}

TEST(MjcfExport, StoveSitesPartsAndInertia) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = test::writeAnalyticStove(dir / "in");
  const auto result =
      exportMjcf(readLabels(labelsPath), dir / "in" / "mesh.obj", dir / "out", {}, labelsPath);
  EXPECT_EQ(result.mainFile, dir / "out" / "my_stove_01" / "my_stove_01.xml");
  const std::string xml = readFileBytes(result.mainFile);
  EXPECT_NE(xml.find("<compiler angle=\"radian\""), std::string::npos);
  for (const char* loc : {"rear_left", "rear_right", "front_left", "front_right"}) {
    EXPECT_NE(xml.find(std::string("<site name=\"burner_on_") + loc + "\" type=\"cylinder\""),
              std::string::npos)
        << loc;
    EXPECT_NE(xml.find(std::string("<site name=\"knob_") + loc + "\""), std::string::npos) << loc;
  }
  EXPECT_NE(
      xml.find("<site name=\"burner_on_front_left\" type=\"cylinder\" pos=\"-0.15 -0.1 0.1\""),
      std::string::npos);
  // The body one STL per material, each knob (a box of the second material) its own; every
  // triangle in one of them.
  EXPECT_TRUE(fs::exists(result.root / "meshes" / "visual_0.stl"));
  EXPECT_FALSE(fs::exists(result.root / "meshes" / "visual_1.stl"));
  for (const char* loc : {"rear_left", "rear_right", "front_left", "front_right"}) {
    EXPECT_TRUE(fs::exists(result.root / "meshes" / (std::string("visual_knob_") + loc + ".stl")));
    EXPECT_NE(xml.find(std::string("<joint name=\"knob_") + loc + "_joint\" type=\"hinge\""),
              std::string::npos);
  }
  EXPECT_EQ(result.visualTriangles, 12 * 5);
  EXPECT_NE(xml.find("class=\"visual\" mesh=\"visual_knob_front_left\""), std::string::npos);
  EXPECT_NE(xml.find("contype=\"0\" conaffinity=\"0\" group=\"1\""), std::string::npos);
  EXPECT_NE(xml.find("<geom name=\"collision_0\" class=\"collision\""), std::string::npos);
  EXPECT_NE(xml.find("<geom name=\"reg_main\" type=\"box\" pos=\"0 -0.01 0.05\" "
                     "size=\"0.3 0.26 0.05\""),
            std::string::npos);
  EXPECT_NE(xml.find("<inertial pos="), std::string::npos);
  EXPECT_GT(result.massKg, 0.0);
  EXPECT_TRUE(result.warnings.empty()) << result.warnings.front();
}

TEST(MjcfExport, CollisionModes) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = test::writeAnalyticStove(dir / "in");
  const ObjectLabels labels = readLabels(labelsPath);
  ExportOptions options;
  options.collision = CollisionMode::None;
  auto r = exportMjcf(labels, dir / "in" / "mesh.obj", dir / "out", options, labelsPath);
  EXPECT_EQ(r.collisionParts, 0);
  EXPECT_EQ(readFileBytes(r.mainFile).find("class=\"collision\" mesh"), std::string::npos);
  options.collision = CollisionMode::Hull;
  r = exportMjcf(labels, dir / "in" / "mesh.obj", dir / "out", options, labelsPath);
  EXPECT_EQ(r.collisionParts, 1);
  EXPECT_FALSE(fs::exists(r.root / "meshes" / "collision_1.stl"));  // the earlier folder replaced
}

TEST(MjcfExport, CuratedMassFromLabels) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = test::writeAnalyticStove(dir / "in");
  ObjectLabels labels = readLabels(labelsPath);
  labels.object.extra["mass_kg"] = 42.5;
  ExportOptions options;
  options.collision = CollisionMode::None;
  const auto r = exportMjcf(labels, dir / "in" / "mesh.obj", dir / "out", options, labelsPath);
  EXPECT_DOUBLE_EQ(r.massKg, 42.5);
  EXPECT_NE(readFileBytes(r.mainFile).find("mass=\"42.5\""), std::string::npos);
}

TEST(ExportObjects, FolderOfObjectsNamesUniqueAndBadFormat) {
  const auto dir = test::freshTempDir();
  test::writeAnalyticStove(dir / "data" / "a", "stove");
  test::writeAnalyticStove(dir / "data" / "b", "stove");
  ExportOptions options;
  options.collision = CollisionMode::Hull;
  const auto mjcf = exportObjects(dir / "data", "mjcf", dir / "mj", options);
  ASSERT_EQ(mjcf.size(), 2u);
  EXPECT_EQ(mjcf[0].root, dir / "mj" / "stove");
  EXPECT_EQ(mjcf[1].root, dir / "mj" / "stove-2");
  const auto og = exportObjects(dir / "data", "omnigibson", dir / "og", options);
  ASSERT_EQ(og.size(), 2u);
  EXPECT_NE(og[0].root, og[1].root);
  EXPECT_EQ(og[0].root.parent_path(), dir / "og" / "stove");
  EXPECT_THROW(exportObjects(dir / "data", "usd", dir / "out"), InvalidArgument);
  EXPECT_THROW(exportObjects(dir / "missing", "mjcf", dir / "out"), FileError);
}

TEST(ExportCli, WritesOneFolderPerObjectWithCollisionFlag) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = test::writeAnalyticStove(dir / "obj");
  const auto r = test::runSagrid("export " + test::shellQuote(labelsPath.string()) +
                                 " --format omnigibson --collision hull --out " +
                                 test::shellQuote((dir / "out").string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "stove" / "mystov" / "urdf" / "mystov.urdf"));
  EXPECT_TRUE(fs::exists(dir / "out" / "stove" / "mystov" / "shape" / "collision" /
                         "mystov_base_link_collision_0.obj"));
  EXPECT_FALSE(fs::exists(dir / "out" / "stove" / "mystov" / "shape" / "collision" /
                          "mystov_base_link_collision_1.obj"));
  const auto bad =
      test::runSagrid("export " + test::shellQuote((dir / "nothing").string()) +
                      " --format mjcf --out " + test::shellQuote((dir / "out").string()));
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find("sagrid: error:"), std::string::npos);
  const auto badFlag = test::runSagrid("export " + test::shellQuote(labelsPath.string()) +
                                       " --format mjcf --collision maybe --out " +
                                       test::shellQuote((dir / "out").string()));
  EXPECT_NE(badFlag.exitCode, 0);
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

// A Sweet Home 3D object names its library and declares its units in a provenance.json beside its
// mesh: in the training set it keeps both, so guards that leave its source out still do.
TEST(TrainingSet, TheMeshsProvenanceRecordGoesWithIt) {
  const auto dir = test::freshTempDir();
  const auto labelsPath = writeObject(dir / "in");
  std::ofstream(dir / "in" / kProvenanceRecordFile) << R"({"library": "Contributions", "meters_per_unit": 0.01})";
  const ObjectLabels labels = readLabels(labelsPath);
  EXPECT_EQ(objectSource(labels, dir / "in" / "mesh.obj", "in"), "Contributions");
  const auto entry = addToTrainingSet(labels, dir / "in" / "mesh.obj", labelsPath, dir / "set");
  EXPECT_EQ(objectSource(readLabels(entry.labels), entry.mesh, "set"), "Contributions");
  ASSERT_TRUE(declaredMetersPerUnit(entry.mesh));
  EXPECT_DOUBLE_EQ(*declaredMetersPerUnit(entry.mesh), 0.01);
  // An object without a record gets none (the training set's folder is then its source).
  const auto bare = addToTrainingSet(labels, writeObject(dir / "bare").parent_path() / "mesh.obj",
                                     dir / "bare" / "labels.json", dir / "other-set");
  EXPECT_FALSE(fs::exists(bare.mesh.parent_path() / kProvenanceRecordFile));
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
