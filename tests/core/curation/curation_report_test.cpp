#include "core/curation/curation_report.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

TEST(CurationLog, WrittenEventsReadBackInOrder) {
  const auto path = test::freshTempDir() / "curation.jsonl";
  CurationLogWriter writer(path);
  EXPECT_EQ(writer.record("stove_a", CurationAction::Open, "stove.glb"), "");
  EXPECT_EQ(writer.record("stove_a", CurationAction::Drag, "Move point"), "");
  const std::vector<CurationEvent> events = readCurationLog(path);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].object, "stove_a");
  EXPECT_EQ(events[1].action, CurationAction::Drag);
  EXPECT_EQ(events[1].detail, "Move point");
  EXPECT_LE(events[0].seconds, events[1].seconds);
}

TEST(CurationLog, ALogThatCannotBeWrittenSaysSoOnceAndABadLineIsNamed) {
  CurationLogWriter writer(test::freshTempDir() / "missing-folder" / "curation.jsonl");
  EXPECT_THAT(writer.record("x", CurationAction::Open), ::testing::HasSubstr("cannot append"));
  EXPECT_EQ(writer.record("x", CurationAction::Open), "");
  const auto bad = test::writeFile(test::freshTempDir() / "bad.jsonl",
                                   "{\"seconds\": 1, \"object\": \"a\", \"action\": \"open\"}\n{\"seconds\": 2, "
                                   "\"object\": \"a\", \"action\": \"fly\"}\n");
  try {
    readCurationLog(bad);
    FAIL() << "read a log with an unknown action";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("line 2 has unknown action 'fly'"));
  }
}

TEST(CurationReport, EditsOneKeyLoggedTimeAndTheKeystrokeModel) {
  const std::vector<CurationEvent> events{
      {100.0, "a", CurationAction::Open, ""},      {101.0, "a", CurationAction::Look, ""},
      {102.5, "a", CurationAction::AcceptAll, ""}, {103.0, "b", CurationAction::Open, ""},
      {105.0, "b", CurationAction::Drag, ""},      {106.0, "b", CurationAction::Undo, ""},
      {108.0, "b", CurationAction::Add, ""},       {500.0, "b", CurationAction::AcceptAll, ""},
      {501.0, "c", CurationAction::Open, ""}};  // c: only opened, not counted
  const CurationReport report = curationReport(events);
  ASSERT_EQ(report.objects.size(), 2u);
  const ObjectCuration& a = report.objects[0];
  EXPECT_TRUE(a.oneKey);
  EXPECT_EQ(a.edits, 0);
  EXPECT_DOUBLE_EQ(a.loggedSeconds, 3.0);
  const KlmOperators ops;
  EXPECT_NEAR(a.klmSeconds, ops.mental + (2 * ops.point + 2 * ops.button) + (ops.mental + ops.keystroke), 1e-9);
  const ObjectCuration& b = report.objects[1];
  EXPECT_FALSE(b.oneKey);
  EXPECT_EQ(b.edits, 2);  // drag and add; the undo is an action, not an edit
  EXPECT_EQ(b.actions.at(CurationAction::Undo), 1);
  // 2 + 1 + 2 + the idle gap capped at kMaxLoggedGapSeconds + 1 s to c's open.
  EXPECT_DOUBLE_EQ(b.loggedSeconds, 5.0 + kMaxLoggedGapSeconds + 1.0);
  EXPECT_DOUBLE_EQ(report.oneKeyShare, 0.5);
  EXPECT_DOUBLE_EQ(report.meanEdits, 1.0);
  EXPECT_NEAR(report.objectsPerHourKlm, 3600.0 / ((a.klmSeconds + b.klmSeconds) / 2), 1e-9);
  EXPECT_THAT(curationMarkdown(report), ::testing::HasSubstr("| 2 | 1.00 | 50.0 % |"));
  EXPECT_EQ(toJson(report)["objects"][1]["actions"]["drag"], 1);
  EXPECT_FALSE(report.replayed);
}

TEST(CurationReport, AReplayedLogSaysItsTimesAreTheMachines) {
  const auto path = test::freshTempDir() / "replayed.jsonl";
  CurationLogWriter writer(path, /*replayed=*/true);
  writer.record("a", CurationAction::Open);
  writer.record("a", CurationAction::AcceptAll);
  const CurationReport report = curationReport(readCurationLog(path));
  EXPECT_TRUE(report.replayed);
  EXPECT_THAT(curationMarkdown(report), ::testing::HasSubstr("the logged times are the machine's"));
}

TEST(CurationReport, AnOpenWithCarriedPointsIsToldApart) {
  const auto path = test::freshTempDir() / "carried.jsonl";
  CurationLogWriter writer(path);
  writer.record("basin_white", CurationAction::Open, "white.glb");
  writer.record("basin_white", CurationAction::Drag, "Move point");
  writer.record("basin_white", CurationAction::AcceptAll);
  writer.record("basin_blue", CurationAction::Open, "blue.glb", "basin_white");
  writer.record("basin_blue", CurationAction::AcceptAll);
  // The line carries the field; a reader that knows nothing of it still reads the open.
  const std::string text = readFileBytes(path);
  EXPECT_THAT(text, ::testing::HasSubstr(R"("carried_from":"basin_white")"));
  const std::vector<CurationEvent> events = readCurationLog(path);
  ASSERT_EQ(events.size(), 5u);
  EXPECT_EQ(events[0].carriedFrom, "");
  EXPECT_EQ(events[3].action, CurationAction::Open);
  EXPECT_EQ(events[3].carriedFrom, "basin_white");
  const CurationReport report = curationReport(events);
  ASSERT_EQ(report.objects.size(), 2u);
  EXPECT_EQ(report.objects[0].carriedFrom, "");
  EXPECT_EQ(report.objects[1].carriedFrom, "basin_white");
  EXPECT_TRUE(report.objects[1].oneKey);
  EXPECT_EQ(report.carriedObjects, 1);
  EXPECT_EQ(toJson(report)["objects"][1]["carried_from"], "basin_white");
  EXPECT_FALSE(toJson(report)["objects"][0].contains("carried_from"));
  EXPECT_THAT(curationMarkdown(report), ::testing::HasSubstr("1 object(s) opened with the points of a curated object"));
}

}  // namespace
}  // namespace sagrid
