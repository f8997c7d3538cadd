// The choice's thresholds fitted on a grid (core/eval/point_scorer_training.h): every combination's
// training cost, and the one taken. A choice is fitted by its edits on the training objects, whose
// probabilities are the classifier's own; the least cost may be a lucky single point of the grid
// whose neighbours cost far more, and a decision fitted that way flips with small changes of its
// training. Judged with its neighbours in the keep and add thresholds, the choice lands in a flat
// minimum instead.
#pragma once

#include <cstddef>
#include <vector>

namespace sagrid {

class ChoiceGrid {
 public:
  // `outer` combinations of the other settings (copy threshold, radius), each with `keeps` keep
  // thresholds and `adds` add thresholds; every cost starts at 0.
  ChoiceGrid(std::size_t outer, std::size_t keeps, std::size_t adds);
  double& cost(std::size_t outer, std::size_t keep, std::size_t add);
  double cost(std::size_t outer, std::size_t keep, std::size_t add) const;
  // The mean cost of the cell (keep, add), which must lie in the grid, and its neighbours one step
  // away in either threshold or both (those inside the grid).
  double neighbourhoodCost(std::size_t outer, std::size_t keep, std::size_t add) const;

  struct Index {
    std::size_t outer = 0, keep = 0, add = 0;
  };
  // The least cost (its neighbourhood's with `smooth`); the first in (outer, keep, add) order on
  // ties. Throws InvalidArgument for an empty grid.
  Index best(bool smooth) const;

 private:
  std::size_t m_outer, m_keeps, m_adds;
  std::vector<double> m_cost;
};

}  // namespace sagrid
