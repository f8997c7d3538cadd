// The found control parts measured against parts a curator confirmed or marked, on a panel with
// two separate knobs whose found parts are known: a marked part equal to the found one agrees
// fully, a half knob with a sideways axis does not; records annotate wrote are no truth.
#include "core/eval/part_agreement.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/common/error.h"
#include "core/controls/control_record.h"
#include "core/eval/part_truth.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"
#include "support/analytic_meshes.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;

void writeObj(const fs::path& path, const Mesh& mesh) {
  std::ofstream obj(path);
  for (const auto& p : mesh.positions) obj << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const auto& t : mesh.triangles) obj << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
}

// An object folder: a 60 x 40 cm panel with `knobs` on it (mesh.obj) and a toggle point at each
// of `points` (labels.json, a z-up stove).
fs::path writeKnobObject(const fs::path& dir, const Mesh& knobs, const std::vector<Eigen::Vector3f>& points) {
  Mesh mesh = test::box({-0.3f, -0.2f, -0.02f}, {0.3f, 0.2f, 0.0f});
  test::append(mesh, knobs);
  fs::create_directories(dir);
  writeObj(dir / "mesh.obj", mesh);
  ObjectLabels labels;
  labels.object.id = dir.filename().string();
  labels.object.mesh = "mesh.obj";
  labels.object.category = "stove";
  labels.object.up = "z";
  for (const auto& at : points) {
    AffordancePoint p;
    p.type = "togglebutton";
    p.position = at;
    labels.affordances.push_back(p);
  }
  writeLabels(dir / "labels.json", labels);
  return dir;
}

// Square knobs at x = -0.1 and +0.1 and a toggle point on each.
fs::path writeKnobPanel(const fs::path& dir) {
  Mesh knobs = test::box({-0.12f, -0.02f, 0.0f}, {-0.08f, 0.02f, 0.025f});
  test::append(knobs, test::box({0.08f, -0.02f, 0.0f}, {0.12f, 0.02f, 0.025f}));
  return writeKnobObject(dir, knobs, {{-0.1f, 0.0f, 0.025f}, {0.1f, 0.0f, 0.025f}});
}

// The imported triangles of the knob at `x` (every corner within it), those with a centroid at
// y >= 0 only when `half`.
std::vector<int> knobTriangles(const Mesh& mesh, float x, bool half) {
  std::vector<int> out;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    bool inKnob = true;
    float y = 0;
    for (int v : mesh.triangles[t]) {
      const Eigen::Vector3f& p = mesh.positions[std::size_t(v)];
      inKnob = inKnob && std::abs(p.x() - x) < 0.021f && std::abs(p.y()) < 0.021f && p.z() > -0.001f;
      y += p.y() / 3.0f;
    }
    if (inKnob && (!half || y >= 0.0f)) out.push_back(static_cast<int>(t));
  }
  return out;
}

TEST(PartAgreement, AMarkedPartEqualToTheFoundOneAgreesAndAHalfKnobDoesNot) {
  const fs::path root = test::freshTempDir();
  const fs::path dir = writeKnobPanel(root / "marked");
  writeKnobPanel(root / "unmarked");
  const Mesh mesh = importMesh(dir / "mesh.obj", ImportOptions(UpAxis::Z));
  ObjectLabels labels = readLabels(dir / "labels.json");
  ControlPart whole = describeControlPart(mesh, knobTriangles(mesh, -0.1f, false), PartOrigin::Marked);
  ASSERT_EQ(whole.triangles.size(), 12u);
  writeControlRecord(labels.affordances[0], {whole, {}, true}, UpAxis::Z);
  ControlPart half = describeControlPart(mesh, knobTriangles(mesh, 0.1f, true), PartOrigin::Marked);
  half.axis = Eigen::Vector3f::UnitX();  // the curator picked a sideways axis
  writeControlRecord(labels.affordances[1], {half, {}, true}, UpAxis::Z);
  // A record annotate wrote (not confirmed) is no truth: the unmarked object has one.
  ObjectLabels other = readLabels(root / "unmarked" / "labels.json");
  writeControlRecord(other.affordances[0], {whole, {}, false}, UpAxis::Z);
  writeLabels(root / "unmarked" / "labels.json", other);
  writeLabels(dir / "labels.json", labels);

  const PartAgreementReport r = measurePartAgreement(
      {{"marked", "stove", dir / "mesh.obj", dir / "labels.json"},
       {"unmarked", "stove", root / "unmarked" / "mesh.obj", root / "unmarked" / "labels.json"}});
  EXPECT_EQ(r.objects, 1u);
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_EQ(r.points[0].point, 1);
  EXPECT_NEAR(r.points[0].iou, 1.0, 1e-9);
  EXPECT_LT(r.points[0].axisDegrees, 1.0);
  EXPECT_GT(r.points[1].iou, 0.2);
  EXPECT_LT(r.points[1].iou, 0.8);
  EXPECT_NEAR(r.points[1].axisDegrees, 90.0, 1.0);
  EXPECT_DOUBLE_EQ(r.shareIouAtLeast08, 0.5);
  EXPECT_DOUBLE_EQ(r.shareAxisWithin10, 0.5);
  // Its source (no provenance here: the dataset folder) gets a row of its own.
  EXPECT_EQ(r.points[0].source, root.filename().string());
  EXPECT_NE(partAgreementMarkdown(r).find("\n| " + root.filename().string() + " | 2 | "),
            std::string::npos)
      << partAgreementMarkdown(r);
  EXPECT_NE(partAgreementMarkdown(r).find("| marked | " + root.filename().string() + " | 2 | knob |"),
            std::string::npos)
      << partAgreementMarkdown(r);
  EXPECT_EQ(toJson(r).at("confirmed_parts"), 2);
  // Each marked knob is checked against its own axis of rotational symmetry (whatever a square
  // block's best one is: AKnobMarkedOffItsOwnAxisShows checks the angle on a round knob).
  for (const auto& p : r.points) {
    ASSERT_TRUE(p.markOffOwnAxisDegrees && p.ownAxisMisfit);
    EXPECT_GE(*p.ownAxisMisfit, 0.0);
    EXPECT_LE(*p.ownAxisMisfit, 1.0);
  }
  EXPECT_TRUE(toJson(r).at("points")[0].contains("mark_off_own_axis_degrees"));

  // An object that cannot be read is named, not thrown.
  std::ofstream(root / "unmarked" / "labels.json") << "{ not json";
  const auto broken = measurePartAgreement(
      {{"unmarked", "stove", root / "unmarked" / "mesh.obj", root / "unmarked" / "labels.json"}});
  ASSERT_EQ(broken.skipped.size(), 1u);
  EXPECT_NE(broken.skipped[0].find("unmarked"), std::string::npos);
}

// The curator's parts kept in a file: measured against them, a copy of the object whose labels
// carry no record reads as the marked original does; a changed mesh is named, not measured; a
// malformed file is one error naming it.
TEST(PartTruth, KeptPartsMeasureAnyCopyAndAChangedMeshIsNamed) {
  const fs::path root = test::freshTempDir();
  const fs::path marked = writeKnobPanel(root / "marked" / "panel");
  const fs::path copy = writeKnobPanel(root / "copy" / "panel");
  const Mesh mesh = importMesh(marked / "mesh.obj", ImportOptions(UpAxis::Z));
  ObjectLabels labels = readLabels(marked / "labels.json");
  ControlPart half = describeControlPart(mesh, knobTriangles(mesh, 0.1f, true), PartOrigin::Marked);
  half.axis = Eigen::Vector3f::UnitX();
  writeControlRecord(labels.affordances[1], {half, {}, true}, UpAxis::Z);
  writeLabels(marked / "labels.json", labels);
  const DatasetEntry original{"panel", "stove", marked / "mesh.obj", marked / "labels.json"};
  const DatasetEntry unmarked{"panel", "stove", copy / "mesh.obj", copy / "labels.json"};

  const fs::path file = root / "part_truth.json";
  std::ofstream(file) << partTruthText(partTruthOf({original, unmarked}));
  const PartTruth truth = readPartTruth(file);
  ASSERT_EQ(truth.objects.size(), 1u);  // the copy's labels confirm nothing
  EXPECT_EQ(truth.objects.at("panel").controls.size(), 1u);
  EXPECT_EQ(truth.objects.at("panel").controls.count(2), 1u);

  EXPECT_TRUE(measurePartAgreement({unmarked}).points.empty());
  const PartAgreementReport fromLabels = measurePartAgreement({original});
  const PartAgreementReport fromTruth = measurePartAgreement({unmarked}, &truth);
  ASSERT_EQ(fromTruth.points.size(), 1u);
  EXPECT_EQ(fromTruth.points[0].point, 2);
  EXPECT_DOUBLE_EQ(fromTruth.points[0].iou, fromLabels.points[0].iou);
  EXPECT_NEAR(fromTruth.points[0].axisDegrees, 90.0, 1.0);
  // The truth, not the labels: a record confirmed in the copy's labels is not measured.
  ObjectLabels copied = readLabels(copy / "labels.json");
  writeControlRecord(copied.affordances[0], {half, {}, true}, UpAxis::Z);
  writeLabels(copy / "labels.json", copied);
  EXPECT_EQ(measurePartAgreement({unmarked}, &truth).points.size(), 1u);

  // A changed mesh: named in skipped, with the object's file.
  std::ofstream(copy / "mesh.obj", std::ios::app) << "v 9 9 9\n";
  const PartAgreementReport changed = measurePartAgreement({unmarked}, &truth);
  EXPECT_TRUE(changed.points.empty());
  ASSERT_EQ(changed.skipped.size(), 1u);
  EXPECT_NE(changed.skipped[0].find("changed since its parts were marked"), std::string::npos)
      << changed.skipped[0];

  // An object of the truth not among the data is named, as is one marked twice.
  const PartAgreementReport elsewhere = measurePartAgreement({}, &truth);
  ASSERT_EQ(elsewhere.skipped.size(), 1u);
  EXPECT_NE(elsewhere.skipped[0].find("panel: marked in"), std::string::npos) << elsewhere.skipped[0];
  EXPECT_THROW(partTruthOf({original, original}), FileError);
  // Two files as one; the same object in both is an error naming the second.
  std::ofstream(root / "empty.json") << R"({"objects": {}})";
  EXPECT_EQ(readPartTruths({root / "empty.json", file}).objects.size(), 1u);
  EXPECT_THROW(readPartTruths({file, file}), FileError);

  for (const char* bad : {"{ not json", R"({"objects": []})", R"({"objects": {"a": {"points": {}}}})",
                          R"({"objects": {"a": {"mesh_sha256": "x", "points": {}}}})",
                          R"({"objects": {"a": {"mesh_sha256": "x", "points": {"zero": {}}}}})",
                          R"({"objects": {"a": {"mesh_sha256": "x", "points": {"02": {}}}}})",
                          R"({"objects": {"a": {"mesh_sha256": "x", "points": {"+2": {}}}}})",
                          R"({"objects": {"a": {"mesh_sha256": "x", "points": {"2": []}}}})"}) {
    std::ofstream(root / "bad.json") << bad;
    EXPECT_THROW(readPartTruth(root / "bad.json"), FileError) << bad;
  }
}

// A round knob on a panel, its record confirmed with `axis`: how far the mark lies from the knob's
// own axis (up) shows.
TEST(PartAgreement, AKnobMarkedOffItsOwnAxisShows) {
  const fs::path dir =
      writeKnobObject(test::freshTempDir() / "round", test::cylinder(0.02f, 0.02f, 48), {{0.0f, 0.0f, 0.02f}});
  ObjectLabels labels = readLabels(dir / "labels.json");
  const Mesh imported = importMesh(dir / "mesh.obj", ImportOptions(UpAxis::Z));
  for (const auto& [axis, degrees] : {std::pair{Eigen::Vector3f::UnitZ().eval(), 0.0},
                                      std::pair{Eigen::Vector3f::UnitX().eval(), 90.0}}) {
    ControlPart knob = describeControlPart(imported, knobTriangles(imported, 0.0f, false), PartOrigin::Marked);
    ASSERT_EQ(knob.motion, ControlMotion::Knob);
    knob.axis = axis;
    writeControlRecord(labels.affordances[0], {knob, {}, true}, UpAxis::Z);
    writeLabels(dir / "labels.json", labels);
    const PartAgreementReport r =
        measurePartAgreement({{"round", "stove", dir / "mesh.obj", dir / "labels.json"}});
    ASSERT_EQ(r.points.size(), 1u);
    ASSERT_TRUE(r.points[0].markOffOwnAxisDegrees && r.points[0].ownAxisMisfit);
    EXPECT_NEAR(*r.points[0].markOffOwnAxisDegrees, degrees, 3.0) << partAgreementMarkdown(r);
    EXPECT_LT(*r.points[0].ownAxisMisfit, 0.05);
  }
}

}  // namespace
}  // namespace sagrid
