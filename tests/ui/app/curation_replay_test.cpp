// The replayed curator: through the GUI session, two objects opened with predictions end with the
// right labels on disk, and the curation log holds exactly the plan's actions.
#include "ui/app/curation_replay.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/curation/curation_report.h"
#include "support/test_paths.h"
#include "ui/app/session.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

// `apex`: the height of the one raised corner (objects of one geometry would start from each
// other's curated points, ui/document/twin_points.h).
void writeObject(const fs::path& dir, const std::vector<AffordancePoint>& predicted, float apex = 0.2f) {
  fs::create_directories(dir);
  std::ofstream(dir / "mesh.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 " << apex
                                  << "\nf 1 2 3\nf 1 3 4\nf 1 2 5\n";
  ObjectLabels labels;
  labels.object.id = dir.filename().string();
  labels.object.mesh = "mesh.obj";
  labels.object.category = "stove";
  labels.object.up = "z";
  labels.affordances = predicted;
  writeLabels(dir / "labels.json", labels);
}

AffordancePoint at(const char* type, float x, float y) {
  AffordancePoint p;
  p.type = type;
  p.position = {x, y, 0};
  return p;
}

TEST(CurationReplay, RightLabelsOnDiskAndThePlansActionsInTheLog) {
  const fs::path dir = test::freshTempDir();
  writeObject(dir / "queue" / "a", {at("heatsource", 0.5f, 0.5f)});
  writeObject(dir / "queue" / "b", {at("heatsource", 0.1f, 0.1f), at("heatsource", 0.9f, 0.9f)}, 0.3f);
  ObjectLabels truthA;
  truthA.object.category = "stove";
  truthA.affordances = {at("heatsource", 0.51f, 0.5f)};
  ObjectLabels truthB;
  truthB.object.category = "stove";
  truthB.affordances = {at("heatsource", 0.1f, 0.5f), at("togglebutton", 0.9f, 0.1f)};
  Session session;
  session.autoPredict = false;
  session.setCurationLog(dir / "curation.jsonl");
  session.openPaths({dir / "queue"});
  const CurationReplaySummary summary = replayCuration(session, [&](const std::string& id) -> std::optional<ObjectLabels> {
    return id == "a" ? truthA : truthB;
  });
  EXPECT_EQ(summary.objects, 2u);
  const ObjectLabels b = readLabels(dir / "queue" / "b" / "labels.json");
  ASSERT_EQ(b.affordances.size(), 2u);
  EXPECT_EQ(b.reviewState, ReviewState::Done);
  const CurationReport report = curationReport(readCurationLog(dir / "curation.jsonl"));
  ASSERT_EQ(report.objects.size(), 2u);
  EXPECT_TRUE(report.objects[0].oneKey);   // a: right within 5 cm, one key
  EXPECT_EQ(report.objects[1].edits, 3);   // b: one drag, one delete, one add
  EXPECT_EQ(report.objects[1].actions.at(CurationAction::Open), 1);
}

}  // namespace
}  // namespace sagrid::ui
