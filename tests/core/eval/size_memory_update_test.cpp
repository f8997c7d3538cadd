#include "core/eval/size_memory_update.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace sagrid {
namespace {

// Each memory below recalls the 2 nearest objects (a fridge's or a microwave's own kind).
// Fridges (1.8 m) and microwaves (0.5 m) of `sources` sources in metres, and `gameKits` game kits
// in units of 0.25 m whose fridges the named units get wrong (a choice made leaving one kit out
// needs another); a mini fridge 0.6 m tall in metres in the first source, which a memory of
// fridges scales wrongly.
std::vector<UnitsCase> appliances(int sources, int gameKits, bool miniFridge = false) {
  std::vector<UnitsCase> cases;
  auto add = [&](const std::string& source, bool fridge, double metersPerUnit, double meters = 0) {
    UnitsCase c;
    c.object.id = source + (meters > 0 ? "/mini-fridge" : fridge ? "/fridge" : "/microwave");
    c.object.source = source;
    c.object.category = "none";
    c.object.descriptor = fridge ? std::vector<float>{1.0f, 0.3f} : std::vector<float>{0.4f, 0.9f};
    c.object.units.largestExtent = (meters > 0 ? meters : fridge ? 1.8 : 0.5) / metersPerUnit;
    c.object.metersPerUnit = metersPerUnit;
    c.group = "g";
    cases.push_back(c);
  };
  for (int i = 0; i < sources; ++i) {
    add("real-" + std::to_string(i), true, 1.0);
    add("real-" + std::to_string(i), false, 1.0);
  }
  for (int i = 0; i < gameKits; ++i) add("game-" + std::to_string(i), true, 0.25);
  if (miniFridge) add("real-0", true, 1.0, 0.6);
  return cases;
}

const std::vector<MemoryRecall> kCandidates = recallCandidates({{SizeMeasure::LargestExtent}}, {2}, {2.0});

TEST(SizeMemoryUpdate, AMemoryThatBeatsTheNamedUnitsIsAdoptedOneThatDoesNotIsRefused) {
  const SizeMemoryUpdate adopted = updateSizeMemory(nullptr, appliances(3, 2), kCandidates, "hash");
  ASSERT_TRUE(adopted.memory);
  EXPECT_EQ(adopted.objects, 8u);
  EXPECT_GT(adopted.rightWithMemory, adopted.rightNamedOnly);
  EXPECT_DOUBLE_EQ(adopted.memory->farFactor(), 2.0);
  EXPECT_EQ(adopted.memory->neighbours(), 2);
  EXPECT_NE(adopted.verdict.find("adopted"), std::string::npos) << adopted.verdict;
  // Objects all in metres: the named units are right on all of them, a memory can only tie.
  const SizeMemoryUpdate refused = updateSizeMemory(nullptr, appliances(3, 0), kCandidates, "hash");
  EXPECT_FALSE(refused.memory);
  EXPECT_NE(refused.verdict.find("refused"), std::string::npos) << refused.verdict;
}

TEST(SizeMemoryUpdate, MoreRightByNoMoreThanItsNoiseIsRefused) {
  // Three game fridges fixed and the mini fridge broken: two more right, and the share wrong moves
  // by exactly its standard error (the rule of every guard, core/common/paired_change.h): refused.
  const SizeMemoryUpdate mixed =
      updateSizeMemory(nullptr, appliances(3, 3, true), kCandidates, "hash");
  EXPECT_EQ(mixed.objects, 10u);
  EXPECT_EQ(mixed.rightWithMemory, mixed.rightNamedOnly + 2);
  EXPECT_NEAR(mixed.change.change(), -2.0 / 10, 1e-12);
  EXPECT_NEAR(mixed.change.noise, 2.0 / 10, 1e-12);
  EXPECT_FALSE(mixed.memory);
  EXPECT_NE(mixed.verdict.find("better by less than its noise"), std::string::npos)
      << mixed.verdict;
  const std::string md = unitsLosoMarkdown(mixed.report);
  EXPECT_NE(md.find("3 fixed, 1 broken (noise 2.0 objects): within its noise."), std::string::npos)
      << md;
  // Two game fridges fixed and nothing broken: beyond the noise.
  const SizeMemoryUpdate clean = updateSizeMemory(nullptr, appliances(3, 2), kCandidates, "hash");
  EXPECT_EQ(clean.rightWithMemory, clean.rightNamedOnly + 2);
  EXPECT_LT(clean.change.change(), -clean.change.noise);
  EXPECT_TRUE(clean.memory);
}

TEST(SizeMemoryUpdate, GrowsAMemoryWithNewObjectsAndRefusesOneOfOtherFeatures) {
  const SizeMemoryUpdate first = updateSizeMemory(nullptr, appliances(3, 2), kCandidates, "hash");
  ASSERT_TRUE(first.memory);
  auto more = appliances(5, 0);
  more.erase(more.begin(), more.begin() + 6);  // sources real-3 and real-4 only
  const SizeMemoryUpdate grown = updateSizeMemory(&*first.memory, more, kCandidates, "hash");
  ASSERT_TRUE(grown.memory);
  EXPECT_EQ(grown.memory->entries().size(), 12u);
  EXPECT_THROW(updateSizeMemory(&*first.memory, more, kCandidates, "other"), InvalidArgument);
  EXPECT_THROW(updateSizeMemory(nullptr, {}, kCandidates, "hash"), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
