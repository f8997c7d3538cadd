#include "core/eval/size_memory_update.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace sagrid {
namespace {

// Each memory below recalls the 2 nearest objects (a fridge's or a microwave's own kind).
// Fridges (1.8 m) and microwaves (0.5 m) of `sources` sources in metres, and two game kits in units
// of 0.25 m whose fridges the named units get wrong (a choice made leaving one kit out needs the
// other).
std::vector<UnitsCase> appliances(int sources, bool withGame) {
  std::vector<UnitsCase> cases;
  auto add = [&](const std::string& source, bool fridge, double metersPerUnit) {
    UnitsCase c;
    c.object.id = source + (fridge ? "/fridge" : "/microwave");
    c.object.source = source;
    c.object.category = "none";
    c.object.descriptor = fridge ? std::vector<float>{1.0f, 0.3f} : std::vector<float>{0.4f, 0.9f};
    c.object.units.largestExtent = (fridge ? 1.8 : 0.5) / metersPerUnit;
    c.object.metersPerUnit = metersPerUnit;
    c.group = "g";
    cases.push_back(c);
  };
  for (int i = 0; i < sources; ++i) {
    add("real-" + std::to_string(i), true, 1.0);
    add("real-" + std::to_string(i), false, 1.0);
  }
  if (withGame) {
    add("game-a", true, 0.25);
    add("game-b", true, 0.25);
  }
  return cases;
}

const std::vector<MemoryRecall> kCandidates = recallCandidates({{SizeMeasure::LargestExtent}}, {2}, {2.0});

TEST(SizeMemoryUpdate, AMemoryThatBeatsTheNamedUnitsIsAdoptedOneThatDoesNotIsRefused) {
  const SizeMemoryUpdate adopted = updateSizeMemory(nullptr, appliances(3, true), kCandidates, "hash");
  ASSERT_TRUE(adopted.memory);
  EXPECT_EQ(adopted.objects, 8u);
  EXPECT_GT(adopted.rightWithMemory, adopted.rightNamedOnly);
  EXPECT_DOUBLE_EQ(adopted.memory->farFactor(), 2.0);
  EXPECT_EQ(adopted.memory->neighbours(), 2);
  EXPECT_NE(adopted.verdict.find("adopted"), std::string::npos) << adopted.verdict;
  // Objects all in metres: the named units are right on all of them, a memory can only tie.
  const SizeMemoryUpdate refused = updateSizeMemory(nullptr, appliances(3, false), kCandidates, "hash");
  EXPECT_FALSE(refused.memory);
  EXPECT_NE(refused.verdict.find("refused"), std::string::npos) << refused.verdict;
}

TEST(SizeMemoryUpdate, GrowsAMemoryWithNewObjectsAndRefusesOneOfOtherFeatures) {
  const SizeMemoryUpdate first = updateSizeMemory(nullptr, appliances(3, true), kCandidates, "hash");
  ASSERT_TRUE(first.memory);
  auto more = appliances(5, false);
  more.erase(more.begin(), more.begin() + 6);  // sources real-3 and real-4 only
  const SizeMemoryUpdate grown = updateSizeMemory(&*first.memory, more, kCandidates, "hash");
  ASSERT_TRUE(grown.memory);
  EXPECT_EQ(grown.memory->entries().size(), 12u);
  EXPECT_THROW(updateSizeMemory(&*first.memory, more, kCandidates, "other"), InvalidArgument);
  EXPECT_THROW(updateSizeMemory(nullptr, {}, kCandidates, "hash"), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
