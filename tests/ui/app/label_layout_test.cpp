#include "ui/app/label_layout.h"

#include <gtest/gtest.h>

namespace sagrid::ui {
namespace {

bool overlap(const PlacedLabel& a, const Eigen::Vector2f& sizeA, const PlacedLabel& b,
             const Eigen::Vector2f& sizeB) {
  return a.topLeft.x() < b.topLeft.x() + sizeB.x() && b.topLeft.x() < a.topLeft.x() + sizeA.x() &&
         a.topLeft.y() < b.topLeft.y() + sizeB.y() && b.topLeft.y() < a.topLeft.y() + sizeA.y();
}

TEST(LabelLayout, ALoneLabelSitsRightOfItsMarkerInFull) {
  // The viewport keeps one layout from frame to frame: a crowded frame before leaves nothing behind.
  LabelLayout layout;
  layout.place(std::vector<LabelRequest>(12, LabelRequest{{100, 100}, {120, 16}, {10, 16}, 1}), 8);
  const auto placed = layout.place({{{100, 100}, {120, 16}, {10, 16}, 1}}, 8);
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_FALSE(placed[0].shortened);
  EXPECT_FLOAT_EQ(placed[0].topLeft.x(), 108);
  EXPECT_FLOAT_EQ(placed[0].topLeft.y(), 92);
}

TEST(LabelLayout, ARowOfKnobsGetsLabelsThatDoNotOverlap) {
  // Four knobs 12 px apart in a row: full labels 120 x 16 px cannot all sit to the right.
  std::vector<LabelRequest> row;
  for (int k = 0; k < 4; ++k) row.push_back({{100.0f + 12.0f * float(k), 200.0f}, {120, 16}, {10, 16}, 1});
  const auto placed = LabelLayout().place(row, 8);
  ASSERT_EQ(placed.size(), 4u);
  auto sizeOf = [&](std::size_t i) { return placed[i].shortened ? row[i].shortSize : row[i].fullSize; };
  int overlapping = 0;
  for (std::size_t a = 0; a < 4; ++a)
    for (std::size_t b = a + 1; b < 4; ++b) overlapping += overlap(placed[a], sizeOf(a), placed[b], sizeOf(b));
  EXPECT_EQ(overlapping, 0);
  EXPECT_FALSE(placed[0].shortened);  // the first keeps its full label
}

TEST(LabelLayout, ADenseRowKeepsEveryNumberAndGrowsTheLabelsThatFit) {
  // A ceramic hob's twelve printed keys 25 px apart: every key keeps a label of its own (its number
  // at least), none over another, and some have room for the full text above or below the row.
  std::vector<LabelRequest> row;
  for (int k = 0; k < 12; ++k) row.push_back({{100.0f + 25.0f * float(k), 300.0f}, {110, 16}, {14, 16}, 1});
  const auto placed = LabelLayout().place(row, 8);
  auto sizeOf = [&](std::size_t i) { return placed[i].shortened ? row[i].shortSize : row[i].fullSize; };
  int overlapping = 0, full = 0;
  for (std::size_t a = 0; a < row.size(); ++a) {
    full += !placed[a].shortened;
    for (std::size_t b = a + 1; b < row.size(); ++b) overlapping += overlap(placed[a], sizeOf(a), placed[b], sizeOf(b));
  }
  EXPECT_EQ(overlapping, 0);
  EXPECT_GE(full, 2);
  EXPECT_LT(full, 12);
}

TEST(LabelLayout, TheSelectedPointsLabelIsPlacedFirstAndKeepsItsSpot) {
  // Two markers on top of each other: the selected one (priority 0, listed second) keeps the
  // right-hand spot in full; the other moves elsewhere.
  const std::vector<LabelRequest> two{{{100, 100}, {120, 16}, {10, 16}, 1},
                                      {{100, 100}, {120, 16}, {10, 16}, 0}};
  const auto placed = LabelLayout().place(two, 8);
  EXPECT_FLOAT_EQ(placed[1].topLeft.x(), 108);
  EXPECT_FALSE(placed[1].shortened);
  EXPECT_FALSE(placed[0].topLeft.isApprox(placed[1].topLeft));
}

TEST(LabelLayout, WithNoFreeSpotTheNumberAloneOverlaps) {
  std::vector<LabelRequest> pile(12, LabelRequest{{100, 100}, {120, 16}, {10, 16}, 1});
  const auto placed = LabelLayout().place(pile, 8);
  EXPECT_TRUE(placed.back().shortened);
  EXPECT_FLOAT_EQ(placed.back().topLeft.x(), 108);
}

}  // namespace
}  // namespace sagrid::ui
