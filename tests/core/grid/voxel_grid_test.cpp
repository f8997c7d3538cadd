#include "core/grid/voxel_grid.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace sagrid {
namespace {

TEST(VoxelGrid, CentreFollowsDesignConvention) {
  const Eigen::Vector3f c = voxelCenter({0, 31, 63}, 64);
  EXPECT_FLOAT_EQ(c.x(), 0.5f / 64 - 0.5f);
  EXPECT_FLOAT_EQ(c.y(), 31.5f / 64 - 0.5f);
  EXPECT_FLOAT_EQ(c.z(), 63.5f / 64 - 0.5f);
}

TEST(VoxelGrid, ContainingIsInverseOfCentreAndClamps) {
  for (int i : {0, 1, 17, 63}) {
    const VoxelIndex v{i, 63 - i, i / 2};
    EXPECT_EQ(voxelContaining(voxelCenter(v, 64), 64), v);
  }
  EXPECT_EQ(voxelContaining({-3.0f, 0.7f, 0.5f}, 64), (VoxelIndex{0, 63, 63}));
  EXPECT_EQ(voxelContaining({-0.5f, 0.0f, 0.4999f}, 64), (VoxelIndex{0, 32, 63}));
}

TEST(VoxelGrid, LinearIndexIsCOrderXSlowest) {
  VoxelGrid grid(4);
  EXPECT_EQ(grid.linearIndex({1, 2, 3}), (1u * 4 + 2) * 4 + 3);
  for (std::size_t n = 0; n < grid.voxelCount(); n += 7) EXPECT_EQ(grid.linearIndex(grid.fromLinear(n)), n);
  EXPECT_EQ(grid.fromLinear(27), (VoxelIndex{1, 2, 3}));
}

TEST(VoxelGrid, OccupancyCountsAndOrders) {
  VoxelGrid grid(8);
  grid.setOccupied({3, 1, 2});
  grid.setOccupied({0, 5, 7});
  grid.setOccupied({3, 1, 2});
  EXPECT_EQ(grid.occupiedCount(), 2u);
  const auto list = grid.occupiedVoxels();
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0], (VoxelIndex{0, 5, 7}));
  EXPECT_EQ(list[1], (VoxelIndex{3, 1, 2}));
  EXPECT_TRUE(grid.contains({7, 7, 7}));
  EXPECT_FALSE(grid.contains({8, 0, 0}));
  EXPECT_FALSE(grid.contains({0, -1, 0}));
}

TEST(VoxelGrid, RejectsBadResolution) {
  EXPECT_THROW(VoxelGrid(0), InvalidArgument);
  EXPECT_THROW(VoxelGrid(5000), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
