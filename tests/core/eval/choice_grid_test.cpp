#include "core/eval/choice_grid.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace sagrid {
namespace {

// One outer setting, 4 keep x 5 add thresholds: a lucky single cell at (0, 4) costs 1 among
// neighbours of 9; a flat valley of cost 2 around (2, 2).
ChoiceGrid luckyAndFlat() {
  ChoiceGrid grid(1, 4, 5);
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t a = 0; a < 5; ++a) grid.cost(0, k, a) = 9;
  grid.cost(0, 0, 4) = 1;
  for (std::size_t k = 1; k <= 3; ++k)
    for (std::size_t a = 1; a <= 3; ++a) grid.cost(0, k, a) = 2;
  return grid;
}

TEST(ChoiceGrid, TheLeastCostTakesTheLuckyCellTheNeighbourhoodTheFlatValley) {
  const ChoiceGrid grid = luckyAndFlat();
  const auto lucky = grid.best(false);
  EXPECT_EQ(lucky.keep, 0u);
  EXPECT_EQ(lucky.add, 4u);
  const auto flat = grid.best(true);
  EXPECT_EQ(flat.keep, 2u);
  EXPECT_EQ(flat.add, 2u);
  // The corner's neighbourhood holds 4 cells, an inner cell's 9.
  EXPECT_DOUBLE_EQ(grid.neighbourhoodCost(0, 0, 4), (1 + 9 + 2 + 9) / 4.0);
  EXPECT_DOUBLE_EQ(grid.neighbourhoodCost(0, 2, 2), 2.0);
}

TEST(ChoiceGrid, TiesGoToTheFirstInOrderAndOuterSettingsDoNotMix) {
  ChoiceGrid grid(2, 2, 2);
  EXPECT_EQ(grid.best(false).outer, 0u);  // all 0: the first
  grid.cost(0, 0, 0) = grid.cost(0, 0, 1) = grid.cost(0, 1, 0) = grid.cost(0, 1, 1) = 5;
  grid.cost(1, 1, 1) = 1;
  // The second outer setting's cells are not the first's neighbours.
  EXPECT_DOUBLE_EQ(grid.neighbourhoodCost(0, 1, 1), 5.0);
  const auto best = grid.best(true);
  EXPECT_EQ(best.outer, 1u);
  EXPECT_THROW(ChoiceGrid(0, 3, 3).best(false), InvalidArgument);
}

}  // namespace
}  // namespace sagrid
