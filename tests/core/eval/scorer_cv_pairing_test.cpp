#include "core/eval/scorer_cv_pairing.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "tests/support/test_paths.h"

namespace sagrid {
namespace {

nlohmann::json figures(double edits, double handPoints = 100, double objects = 20) {
  return {{"edits", edits * handPoints}, {"edits_per_hand_point", edits},
          {"hand_points", handPoints}, {"objects", objects}, {"one_key_share", 0.25},
          {"single_error_m", 0.07}};
}

// A scorer_cv.json with the full run at `full` and one repeat per value of `repeats` (seeds 1...),
// the unseen sources' figures 0.1 above.
nlohmann::json report(double full, const std::vector<double>& repeats) {
  nlohmann::json r = nlohmann::json::array();
  for (std::size_t i = 0; i < repeats.size(); ++i)
    r.push_back({{"seed", i + 1},
                 {"with_curated", figures(repeats[i])},
                 {"unseen_with_curated", figures(repeats[i] + 0.1, 50, 10)}});
  return {{"all", {{"with_curated", figures(full)}}},
          {"unseen", {{"with_curated", figures(full + 0.1, 50, 10)}}},
          {"spread", {{"left_out_generated_share", 0.2}, {"repeats", r}}}};
}

std::filesystem::path write(const std::filesystem::path& dir, const std::string& name,
                            const nlohmann::json& j) {
  const auto file = dir / name;
  std::ofstream(file) << j.dump();
  return file;
}

TEST(ScorerCvPairing, PairsTwoRunsRepeatByRepeatAndCountsWhichNeedsFewerEdits) {
  const auto dir = test::freshTempDir("scorer_cv_pairing");
  const auto a = readScorerCv(write(dir, "a.json", report(0.50, {0.50, 0.55, 0.60, 0.58})));
  const auto b = readScorerCv(write(dir, "b.json", report(0.52, {0.52, 0.55, 0.64, 0.57})));
  const PairedScorerCv p = pairScorerCvs(a, b);
  ASSERT_EQ(p.edits.size(), 4u);
  EXPECT_NEAR(p.all.difference(), -0.02, 1e-9);
  EXPECT_NEAR(p.edits[2].difference(), -0.04, 1e-9);
  EXPECT_EQ(p.fewer, 2);
  EXPECT_EQ(p.more, 1);
  EXPECT_EQ(p.same, 1);
  EXPECT_NEAR(p.signTestP, 1.0, 1e-9);  // 2 against 1 is no evidence
  EXPECT_EQ(p.unseenFewer, 2);
  const std::string md = pairedScorerCvMarkdown(p);
  EXPECT_NE(md.find("| 3 | 0.600 | 0.640 | -0.040 |"), std::string::npos) << md;
  EXPECT_NE(md.find("2 / 1 / 1"), std::string::npos) << md;
  // A difference that prints as zero has no sign.
  EXPECT_NE(md.find("| 2 | 0.550 | 0.550 | 0.000 |"), std::string::npos) << md;
}

TEST(ScorerCvPairing, TheSignTestIsTheExactBinomialTail) {
  EXPECT_DOUBLE_EQ(signTestP(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(signTestP(5, 0), 2.0 / 32);
  EXPECT_DOUBLE_EQ(signTestP(0, 5), 2.0 / 32);
  EXPECT_NEAR(signTestP(1, 9), 2.0 * 11 / 1024, 1e-12);
  EXPECT_DOUBLE_EQ(signTestP(3, 3), 1.0);
}

TEST(ScorerCvPairing, RefusesRunsWhoseRepeatsDoNotPair) {
  const auto dir = test::freshTempDir("scorer_cv_pairing_refused");
  const auto a = readScorerCv(write(dir, "a.json", report(0.5, {0.5, 0.6})));
  // Another repeat count; no repeats at all; another left-out share; other curated objects.
  EXPECT_THROW(pairScorerCvs(a, readScorerCv(write(dir, "b.json", report(0.5, {0.5, 0.6, 0.7})))),
               InvalidArgument);
  nlohmann::json none = report(0.5, {});
  none.erase("spread");
  EXPECT_THROW(pairScorerCvs(a, readScorerCv(write(dir, "c.json", none))), InvalidArgument);
  nlohmann::json share = report(0.5, {0.5, 0.6});
  share["spread"]["left_out_generated_share"] = 0.3;
  EXPECT_THROW(pairScorerCvs(a, readScorerCv(write(dir, "d.json", share))), InvalidArgument);
  nlohmann::json other = report(0.5, {0.5, 0.6});
  other["spread"]["repeats"][1]["with_curated"] = figures(0.6, 120);
  try {
    pairScorerCvs(a, readScorerCv(write(dir, "e.json", other)));
    FAIL() << "other curated objects were paired";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("e.json"), std::string::npos) << e.what();
  }
}

TEST(ScorerCvPairing, AFileThatIsNoReportIsOneErrorNamingIt) {
  const auto dir = test::freshTempDir("scorer_cv_pairing_bad");
  std::ofstream(dir / "bad.json") << "{\"all\": 3}";
  try {
    readScorerCv(dir / "bad.json");
    FAIL() << "a malformed report was read";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "truncated.json") << "{\"all\": {\"with_cu";
  EXPECT_THROW(readScorerCv(dir / "truncated.json"), FileError);
  EXPECT_THROW(readScorerCv(dir / "missing.json"), Error);
}

// `report` with its repeats' seeds starting at `firstSeed`.
nlohmann::json reportFrom(unsigned firstSeed, double full, const std::vector<double>& repeats) {
  nlohmann::json j = report(full, repeats);
  for (std::size_t i = 0; i < repeats.size(); ++i) j["spread"]["repeats"][i]["seed"] = firstSeed + i;
  return j;
}

TEST(ScorerCvPairing, OneDesignsRunsWithOtherSeedsPoolTheirRepeats) {
  const auto dir = test::freshTempDir("scorer_cv_pooling");
  const auto later = readScorerCv(write(dir, "later.json", reportFrom(3, 0.5, {0.7, 0.8})));
  const auto first = readScorerCv(write(dir, "first.json", reportFrom(1, 0.5, {0.5, 0.6})));
  const RecordedScorerCv pooled = pooledScorerCvs({later, first});
  EXPECT_EQ(pooled.seeds, (std::vector<unsigned>{1, 2, 3, 4}));
  ASSERT_EQ(pooled.repeatsAll.size(), 4u);
  EXPECT_DOUBLE_EQ(pooled.repeatsAll[2].editsPerHandPoint, 0.7);
  // A seed twice, or a run of another design (its full run differs), does not pool.
  EXPECT_THROW(pooledScorerCvs({first, first}), InvalidArgument);
  const auto other = readScorerCv(write(dir, "other.json", reportFrom(5, 0.45, {0.5})));
  EXPECT_THROW(pooledScorerCvs({first, other}), InvalidArgument);
  EXPECT_THROW(pooledScorerCvs({}), InvalidArgument);
}

TEST(ScorerCvPairing, TheCommandReadsRunFoldersAndWritesTheReport) {
  const auto dir = test::freshTempDir("scorer_cv_pairing_cli");
  std::filesystem::create_directories(dir / "a");
  write(dir / "a", "scorer_cv.json", report(0.5, {0.5, 0.6}));
  write(dir, "b.json", report(0.5, {0.6, 0.7}));
  auto r = test::runSagrid("scorer compare " + test::quotedPath(dir / "a") + " " +
                           test::quotedPath(dir / "b.json") + " --out " +
                           test::quotedPath(dir / "paired.md"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("2 / 0 / 0"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "paired.md"));
  // Runs with other seeds, comma-separated, pool: 4 repeats a side.
  write(dir, "a2.json", reportFrom(3, 0.5, {0.5, 0.6}));
  write(dir, "b2.json", reportFrom(3, 0.5, {0.6, 0.7}));
  r = test::runSagrid("scorer compare " + test::quotedPath(dir / "a") + "," +
                      test::quotedPath(dir / "a2.json") + " " + test::quotedPath(dir / "b.json") +
                      "," + test::quotedPath(dir / "b2.json"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("4 / 0 / 0"), std::string::npos) << r.output;
  write(dir, "c.json", report(0.5, {0.6}));
  r = test::runSagrid("scorer compare " + test::quotedPath(dir / "a") + " " +
                      test::quotedPath(dir / "c.json"));
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("do not pair"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sagrid
