#include "core/grid/top_relief.h"

#include <gtest/gtest.h>

#include <functional>

namespace sagrid {
namespace {

constexpr int kN = 64;

// A footprint of columns [10, 50)^2 standing on k = 0, each column's top at height(x, y).
std::vector<VoxelIndex> columns(const std::function<int(int, int)>& height) {
  std::vector<VoxelIndex> out;
  for (int x = 10; x < 50; ++x)
    for (int y = 10; y < 50; ++y) {
      out.push_back({x, y, 0});
      out.push_back({x, y, height(x, y)});
    }
  return out;
}

TEST(TopRelief, AFlatLidIsAllTopNoBasinNoSpots) {
  const auto r = topRelief(columns([](int, int) { return 30; }), kN);
  EXPECT_FLOAT_EQ(r[0], 1.0f);  // flat top
  EXPECT_FLOAT_EQ(r[1], 0.0f);  // basin
  EXPECT_FLOAT_EQ(r[2], 0.0f);
  EXPECT_FLOAT_EQ(r[3], 0.0f);  // raised spots
  EXPECT_FLOAT_EQ(r[4], 0.0f);  // sunken spots
  EXPECT_FLOAT_EQ(r[5], 0.0f);  // spot count
  EXPECT_FLOAT_EQ(r[6], 1.0f);  // upper share
}

TEST(TopRelief, ABasinEnclosedByItsRimIsFoundWithItsDepth) {
  const auto r = topRelief(
      columns([](int x, int y) { return x >= 20 && x < 40 && y >= 20 && y < 40 ? 15 : 30; }), kN);
  EXPECT_FLOAT_EQ(r[1], 400.0f / 1600.0f);
  EXPECT_NEAR(r[2], 15.0f / 31.0f, 1e-6f);
  EXPECT_FLOAT_EQ(r[0], 1200.0f / 1600.0f);
}

TEST(TopRelief, ALowerStepOpenToOneSideIsNoBasin) {
  // A counter with a lower shelf along one edge: no rim on that side.
  const auto r = topRelief(columns([](int x, int) { return x < 20 ? 15 : 30; }), kN);
  EXPECT_FLOAT_EQ(r[1], 0.0f);
  EXPECT_FLOAT_EQ(r[2], 0.0f);
}

TEST(TopRelief, BurnerSpotsAreCountedOneEach) {
  // Four 3x3 burner caps two voxels above a flat top.
  auto onCap = [](int x, int y) {
    for (int cx : {18, 38})
      for (int cy : {18, 38})
        if (std::abs(x - cx) <= 1 && std::abs(y - cy) <= 1) return true;
    return false;
  };
  const auto r = topRelief(columns([&](int x, int y) { return onCap(x, y) ? 32 : 30; }), kN);
  EXPECT_FLOAT_EQ(r[5], 4.0f);
  EXPECT_FLOAT_EQ(r[3], 36.0f / 1600.0f);
  EXPECT_FLOAT_EQ(r[0], 36.0f / 1600.0f);  // only the caps are within a voxel of the highest
}

TEST(TopRelief, NothingForNoVoxels) {
  for (float v : topRelief({}, kN)) EXPECT_EQ(v, 0.0f);
  for (float v : topRelief({{1, 2, 3}}, 0)) EXPECT_EQ(v, 0.0f);
}

}  // namespace
}  // namespace sagrid
