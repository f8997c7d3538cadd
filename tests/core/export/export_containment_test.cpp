// Containment of the simulator exports and "Add to training set" (issue 14): ids and names from
// data, labels' object.mesh, an OBJ's mtllib and an MTL's textures are attacked with absolute
// paths, ../ chains, NUL bytes, markup characters and 300-character names. Nothing may be read
// from or written to anywhere but the object's folder and the output folder, and the XML stays
// well-formed (ids are escaped).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/export/export_objects.h"
#include "core/export/mjcf_export.h"
#include "core/export/omnigibson_export.h"
#include "core/export/training_set.h"
#include "core/mesh/mesh_export.h"
#include "support/folder_listing.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace std::string_literals;

// Every entry under `root` that was not there `before` lies under `out`.
void expectNewEntriesOnlyUnder(const fs::path& root, const std::set<fs::path>& before,
                               const fs::path& out) {
  for (const auto& path : test::entriesBelow(root)) {
    if (before.count(path)) continue;
    const auto rel = path.lexically_relative(out);
    EXPECT_FALSE(rel.empty() || *rel.begin() == "..") << "written outside " << out << ": " << path;
    EXPECT_LE(path.filename().string().size(), 255u) << path;
  }
}

std::vector<std::string> hostileNames() {
  return {"../../escape",
          "../../../../../../tmp/sagrid-escape",
          "/tmp/sagrid-absolute",
          "a\0b/../../c"s,
          "<x>\"&'y",
          std::string(300, 'n'),
          "..",
          ".",
          "sub/dir/name",
          "C:\\windows\\x",
          "\xff\xfe"};
}

TEST(ExportContainment, HostileIdsNeverLeaveTheOutputFolder) {
  const auto root = test::freshTempDir();
  const auto labelsPath = test::writeAnalyticStove(root / "in");
  const auto before = test::entriesBelow(root);
  ExportOptions options;
  options.collision = CollisionMode::None;
  ExportNames names;  // one run: ids that map to the same file name still get their own folder
  options.names = &names;
  std::set<fs::path> roots;
  for (const auto& id : hostileNames()) {
    SCOPED_TRACE(json(id).dump(-1, ' ', false, json::error_handler_t::replace));
    ObjectLabels labels = readLabels(labelsPath);
    labels.object.id = id;
    labels.object.category = id;  // the OmniGibson category folder comes from data too
    const auto mjcf =
        exportMjcf(labels, root / "in" / "mesh.obj", root / "out", options, labelsPath);
    const auto og =
        exportOmniGibson(labels, root / "in" / "mesh.obj", root / "out", options, labelsPath);
    EXPECT_TRUE(roots.insert(mjcf.root).second) << mjcf.root;
    EXPECT_TRUE(roots.insert(og.root).second) << og.root;
    // The model attribute closes where it should and holds no raw markup.
    const std::string xml = readFileBytes(mjcf.mainFile);
    const std::size_t start = xml.find("<mujoco model=\"") + 15;
    const std::size_t end = xml.find('"', start);
    EXPECT_EQ(xml.substr(end, 2), "\">");
    EXPECT_EQ(xml.substr(start, end - start).find_first_of("<>"), std::string::npos);
  }
  expectNewEntriesOnlyUnder(root, before, root / "out");
  // The markup id is escaped in the MJCF: <mujoco model="&lt;x&gt;&quot;&amp;&apos;y">.
  bool escaped = false;
  for (const auto& path : test::entriesBelow(root / "out"))
    if (path.extension() == ".xml" &&
        readFileBytes(path).find("model=\"&lt;x&gt;&quot;&amp;&apos;y\"") != std::string::npos)
      escaped = true;
  EXPECT_TRUE(escaped);
}

TEST(ExportContainment, ObjectMeshOutsideTheObjectFolderIsRefused) {
  const auto root = test::freshTempDir();
  test::writeAnalyticStove(root / "outside");  // a perfectly good mesh, but not this object's
  const auto labelsPath = test::writeAnalyticStove(root / "data" / "obj");
  const std::vector<std::string> references = {"../../outside/mesh.obj",
                                               (root / "outside" / "mesh.obj").string(),
                                               "/etc/hostname",
                                               "mesh\0.obj"s,
                                               "sub/../../../outside/mesh.obj",
                                               std::string(300, 'm') + ".obj",
                                               "..\\..\\outside\\mesh.obj"};
  for (const auto& reference : references) {
    json j = json::parse(readFileBytes(labelsPath));
    j["object"]["mesh"] = reference;
    writeFileAtomic(labelsPath, j.dump());
    for (const char* format : {"mjcf", "omnigibson"}) {
      try {
        exportObjects(labelsPath, format, root / "out");
        ADD_FAILURE() << "accepted object.mesh " << reference.substr(0, 60);
      } catch (const FileError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(labelsPath.string(), 0), 0u) << e.what();
      }
    }
  }
  EXPECT_TRUE(test::entriesBelow(root / "out").empty());
}

// `annotate --out OUT` writes object.mesh relative to OUT/<id>/ ("../../data/x/mesh.obj"):
// export refuses it unless the user names the data folder as mesh root (export --mesh-root).
TEST(ExportContainment, AnnotateOutLabelsExportWithTheDataFolderAsMeshRoot) {
  const auto root = test::freshTempDir();
  const auto dataLabels = test::writeAnalyticStove(root / "data" / "x");
  json j = json::parse(readFileBytes(dataLabels));
  j["object"]["mesh"] = "../../data/x/mesh.obj";
  fs::create_directories(root / "out" / "x");
  writeFileAtomic(root / "out" / "x" / "labels.json", j.dump());
  fs::remove(dataLabels);
  ExportOptions options;
  options.collision = CollisionMode::None;
  EXPECT_THROW(exportObjects(root / "out", "mjcf", root / "export", options), FileError);
  options.meshRoot = root / "data";
  const auto results = exportObjects(root / "out", "mjcf", root / "export", options);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_TRUE(fs::is_regular_file(results[0].mainFile));
  // The root widens the folder, not the rule: a climb out of it is still refused.
  j["object"]["mesh"] = "../../data/../../../../etc/hostname";
  writeFileAtomic(root / "out" / "x" / "labels.json", j.dump());
  EXPECT_THROW(exportObjects(root / "out", "mjcf", root / "export2", options), FileError);
}

// An OBJ naming an MTL outside its folder, or an MTL naming a texture outside, is refused by the
// exports and by "Add to training set": neither reads it nor copies it anywhere.
TEST(ExportContainment, MtllibAndTexturesOutsideTheObjectFolderAreRefused) {
  const auto root = test::freshTempDir();
  fs::create_directories(root / "secret");
  std::ofstream(root / "secret" / "evil.mtl") << "newmtl evil\nKd 0.123 0.456 0.789\n";
  std::ofstream(root / "secret" / "secret.png") << "not for export";
  const auto labelsPath = test::writeAnalyticStove(root / "obj");
  const std::string obj = readFileBytes(root / "obj" / "mesh.obj");
  const std::string body = obj.substr(obj.find('\n') + 1);  // without the mtllib line
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"mtllib ../secret/evil.mtl\n", ""},
      {"mtllib " + (root / "secret" / "evil.mtl").string() + "\n", ""},
      {"mtllib mesh.mtl\n", "newmtl body\nKd 1 1 1\nmap_Kd ../secret/secret.png\n"},
      {"mtllib mesh.mtl\n", "newmtl body\nmap_Kd -s 1 1 1 /etc/hostname\n"}};
  const auto before = test::entriesBelow(root);
  for (const auto& [mtllib, mtl] : cases) {
    SCOPED_TRACE(mtllib + mtl);
    writeFileAtomic(root / "obj" / "mesh.obj", mtllib + body);
    if (!mtl.empty()) writeFileAtomic(root / "obj" / "mesh.mtl", mtl);
    for (const char* format : {"mjcf", "omnigibson"})
      EXPECT_THROW(exportObjects(labelsPath, format, root / "out"), FileError) << format;
    EXPECT_THROW(addToTrainingSet(readLabels(labelsPath), root / "obj" / "mesh.obj", labelsPath,
                                  root / "set"),
                 FileError);
  }
  for (const auto& path : test::entriesBelow(root)) {
    if (before.count(path) || path.parent_path() == root / "obj") continue;
    ADD_FAILURE() << "written: " << path;
  }
}

// Material names come from the mesh file; in the OmniGibson visual MTL they stay plain names, so
// a name holding a line break cannot add a texture line pointing anywhere.
TEST(ExportContainment, MaterialNamesCannotInjectMtlLines) {
  const auto root = test::freshTempDir();
  Mesh mesh = test::analyticStoveMesh();
  mesh.materials[1].name = "knob\nmap_Kd /etc/hostname\nnewmtl x";
  fs::create_directories(root / "in");
  exportMesh(mesh, root / "in" / "mesh.glb");
  ObjectLabels labels;
  labels.object.id = "stove";
  labels.object.category = "stove";
  labels.object.up = "y";  // glTF's axis
  labels.object.extra["units"] = "m";
  ExportOptions options;
  options.collision = CollisionMode::None;
  const auto r = exportOmniGibson(labels, root / "in" / "mesh.glb", root / "out", options);
  const std::string mtl = readFileBytes(r.root / "shape" / "visual" /
                                        (r.root.filename().string() + "_base_link_visual.mtl"));
  EXPECT_EQ(mtl.find("/etc/hostname"), std::string::npos) << mtl;
  EXPECT_EQ(mtl.find("\nmap_Kd"), std::string::npos) << mtl;
}

TEST(ExportContainment, TrainingSetIdsStayInsideTheDataset) {
  const auto root = test::freshTempDir();
  const auto labelsPath = test::writeAnalyticStove(root / "obj");
  const auto before = test::entriesBelow(root);
  for (const auto& id : hostileNames()) {
    ObjectLabels labels = readLabels(labelsPath);
    labels.object.id = id;
    const auto entry =
        addToTrainingSet(labels, root / "obj" / "mesh.obj", labelsPath, root / "set");
    EXPECT_EQ(entry.labels.parent_path().parent_path(), root / "set");
  }
  expectNewEntriesOnlyUnder(root, before, root / "set");
}

}  // namespace
}  // namespace sagrid
