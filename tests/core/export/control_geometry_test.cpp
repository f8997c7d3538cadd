// The moving parts of an export from labels: the curator's records used as given, a part that
// would take most of the object refused (site only, warning), records naming triangles the mesh
// lacks refused with the labels file named, and knobs that cannot be paired as recorded paired by
// layout with a warning.
#include "core/export/control_geometry.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/controls/control_record.h"
#include "core/export/mjcf_export.h"
#include "core/mesh/mesh_import.h"
#include "support/labelled_objects.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;

struct Stove {
  fs::path labelsPath;
  ObjectLabels labels;
  Mesh mesh;
};

Stove analyticStove() {
  const auto dir = test::freshTempDir();
  Stove s;
  s.labelsPath = test::writeAnalyticStove(dir / "in");
  s.labels = readLabels(s.labelsPath);
  s.mesh = importMesh(dir / "in" / "mesh.obj");
  return s;
}

AffordancePoint& firstKnob(ObjectLabels& labels) {
  for (auto& p : labels.affordances)
    if (p.type == "togglebutton") return p;
  throw Error("no knob");
}

TEST(ControlGeometry, EveryKnobOfTheAnalyticStoveIsCutFromTheBody) {
  Stove s = analyticStove();
  std::vector<std::string> warnings;
  const auto split = exportdetail::splitControls(s.labels, s.mesh, 1.0, s.labelsPath, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_EQ(split.controls.size(), 4u);
  int body = 0;
  for (bool b : split.body) body += b;
  EXPECT_EQ(body, 12);  // the stove's own box; each knob's 12 triangles left with its part
  for (const auto& c : split.controls) {
    EXPECT_EQ(c.part.triangles.size(), 12u);
    EXPECT_GT(c.mass.mass, 0.0);
    EXPECT_EQ(c.mesh.triangles.size(), 12u);
  }
}

TEST(ControlGeometry, APartTakingMostOfTheObjectStaysASite) {
  Stove s = analyticStove();
  ControlRecord record;
  for (int t = 0; t < static_cast<int>(s.mesh.triangles.size()); ++t) record.part.triangles.push_back(t);
  writeControlRecord(firstKnob(s.labels), record, UpAxis::Z);
  std::vector<std::string> warnings;
  const auto split = exportdetail::splitControls(s.labels, s.mesh, 1.0, s.labelsPath, warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("most of the object; site only"), std::string::npos) << warnings[0];
  EXPECT_EQ(split.controls.size(), 3u);
}

TEST(ControlGeometry, ARecordBeyondTheMeshNamesTheLabelsFile) {
  Stove s = analyticStove();
  ControlRecord record;
  record.part.triangles = {5, 1000};
  writeControlRecord(firstKnob(s.labels), record, UpAxis::Z);
  std::vector<std::string> warnings;
  try {
    exportdetail::splitControls(s.labels, s.mesh, 1.0, s.labelsPath, warnings);
    ADD_FAILURE() << "accepted";
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), s.labelsPath);
    EXPECT_NE(std::string(e.what()).find("triangle 1000"), std::string::npos) << e.what();
  }
}

TEST(ControlGeometry, KnobsThatCannotBePairedAsRecordedArePairedByLayout) {
  Stove s = analyticStove();
  // Every knob records burner 0: driven four times.
  const fs::path dir = s.labelsPath.parent_path();
  for (auto& p : s.labels.affordances)
    if (p.type == "togglebutton") {
      ControlRecord record;
      record.part = describeControlPart(s.mesh, {}, PartOrigin::Disc);
      record.part.radius = 0.01f;
      record.part.pivot = p.position;
      record.drives = 0;
      writeControlRecord(p, record, UpAxis::Z);
    }
  const auto result = exportMjcf(s.labels, dir / "mesh.obj", dir.parent_path() / "out", {}, s.labelsPath);
  bool warned = false;
  for (const auto& w : result.warnings) warned = warned || w.find("paired by layout") != std::string::npos;
  EXPECT_TRUE(warned);
  // A stove with more burners than knobs: the burner left over never lights, and says so.
  s = analyticStove();
  s.labels.affordances.erase(
      std::find_if(s.labels.affordances.begin(), s.labels.affordances.end(),
                   [](const AffordancePoint& p) { return p.type == "togglebutton"; }));
  const auto fewer = exportMjcf(s.labels, s.labelsPath.parent_path() / "mesh.obj",
                                s.labelsPath.parent_path().parent_path() / "out2", {}, s.labelsPath);
  int unlit = 0;
  for (const auto& w : fewer.warnings) unlit += w.find("has no knob") != std::string::npos;
  EXPECT_EQ(unlit, 1);
}

}  // namespace
}  // namespace sagrid
