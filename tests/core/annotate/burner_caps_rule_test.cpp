#include "core/annotate/burner_caps_rule.h"

#include <gtest/gtest.h>

#include "core/annotate/category_evidence.h"
#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

// A counter 1 m x 0.6 m with `caps` equal flat squares `width` across standing on it.
Mesh counterWithCaps(int caps, float width) {
  Mesh mesh = test::box({0, 0, 0}, {1.0f, 0.6f, 0.05f});
  for (int i = 0; i < caps; ++i) {
    const Eigen::Vector3f lo(0.1f + 0.25f * static_cast<float>(i), 0.2f, 0.05f);
    test::append(mesh, test::box(lo, lo + Eigen::Vector3f(width, width, 0.02f)));
  }
  return mesh;
}

CategoryDecision decided(const std::string& category, double score = 0.8) {
  CategoryDecision d;
  d.category = d.best = category;
  d.score = score;
  return d;
}

TEST(BurnerCaps, ThreeEqualRoundFlatPartsOfSizeAreCaps) {
  EXPECT_TRUE(hasBurnerCaps(counterWithCaps(3, 0.12f)));
  EXPECT_TRUE(hasBurnerCaps(counterWithCaps(4, 0.12f)));
  // Two (a double sink's drains), or tap knobs 3 cm across on a 1 m counter.
  EXPECT_FALSE(hasBurnerCaps(counterWithCaps(2, 0.12f)));
  EXPECT_FALSE(hasBurnerCaps(counterWithCaps(4, 0.03f)));
  // Tall parts are not caps (round, but not flat).
  Mesh posts = test::box({0, 0, 0}, {1.0f, 0.6f, 0.05f});
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3f lo(0.1f + 0.25f * static_cast<float>(i), 0.2f, 0.05f);
    test::append(posts, test::box(lo, lo + Eigen::Vector3f(0.12f, 0.12f, 0.2f)));
  }
  EXPECT_FALSE(hasBurnerCaps(posts));
  EXPECT_FALSE(hasBurnerCaps(Mesh{}));
}

TEST(BurnerCaps, EachRoundFlatPartListsItsFamilyWithTheirWidths) {
  // Three caps 0.12 wide on a counter 1 m long: each lists the three, itself first.
  const auto families = roundFlatFamilies(counterWithCaps(3, 0.12f));
  ASSERT_EQ(families.size(), 3u);
  for (const auto& family : families) {
    ASSERT_EQ(family.widthShares.size(), 3u);
    for (float share : family.widthShares) EXPECT_NEAR(share, 0.12f, 1e-4f);
  }
  EXPECT_TRUE(roundFlatFamilies(Mesh{}).empty());
}

TEST(BurnerCaps, OnlyASinkDecisionTurnsIntoAStoveOne) {
  const Mesh withCaps = counterWithCaps(3, 0.12f);
  int read = 0;
  const auto mesh = [&] { return ++read, hasBurnerCaps(withCaps); };
  const auto sink = withBurnerCaps(decided("sink", 0.79), mesh);
  EXPECT_EQ(sink.category, "stove");
  EXPECT_EQ(sink.best, "stove");
  EXPECT_TRUE(sink.byBurnerCaps);
  EXPECT_DOUBLE_EQ(sink.score, 0.79);
  EXPECT_EQ(read, 1);
  // A stove stays a stove, a rejected object rejected; the mesh is not read for them.
  EXPECT_FALSE(withBurnerCaps(decided("stove"), mesh).byBurnerCaps);
  CategoryDecision rejected = decided(kRejectedCategory);
  rejected.rejected = true;
  rejected.best = "sink";
  EXPECT_TRUE(withBurnerCaps(rejected, mesh).rejected);
  EXPECT_EQ(read, 1);
  // Without caps the sink stays a sink.
  const auto bare =
      withBurnerCaps(decided("sink"), [] { return hasBurnerCaps(counterWithCaps(2, 0.12f)); });
  EXPECT_EQ(bare.category, "sink");
  EXPECT_FALSE(bare.byBurnerCaps);
}

TEST(BurnerCaps, TheStoveModelsCheckATurnedDecisionHoweverSureTheClassifierWas) {
  EvidenceGate gate;
  gate.thresholds["stove"] = 0.4;
  gate.sureProbability = 0.95;
  CategoryDecision turned = decided("stove", 0.99);
  turned.byBurnerCaps = true;
  int asked = 0;
  const auto weak = [&asked](const std::string&) { return ++asked, 0.1; };
  EXPECT_TRUE(applyEvidenceGate(turned, gate, weak).rejected);
  EXPECT_EQ(asked, 1);
  const auto strong = [](const std::string&) { return 0.5; };
  EXPECT_EQ(applyEvidenceGate(turned, gate, strong).category, "stove");
}

}  // namespace
}  // namespace sagrid
