#include "core/eval/choice_grid.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"

namespace sagrid {

ChoiceGrid::ChoiceGrid(std::size_t outer, std::size_t keeps, std::size_t adds)
    : m_outer(outer), m_keeps(keeps), m_adds(adds), m_cost(outer * keeps * adds, 0.0) {}

double& ChoiceGrid::cost(std::size_t outer, std::size_t keep, std::size_t add) {
  return m_cost[(outer * m_keeps + keep) * m_adds + add];
}

double ChoiceGrid::cost(std::size_t outer, std::size_t keep, std::size_t add) const {
  return m_cost[(outer * m_keeps + keep) * m_adds + add];
}

double ChoiceGrid::neighbourhoodCost(std::size_t outer, std::size_t keep, std::size_t add) const {
  double sum = 0;
  int n = 0;
  for (std::size_t k = keep ? keep - 1 : 0; k <= std::min(keep + 1, m_keeps - 1); ++k)
    for (std::size_t a = add ? add - 1 : 0; a <= std::min(add + 1, m_adds - 1); ++a) {
      sum += cost(outer, k, a);
      ++n;
    }
  return sum / n;
}

ChoiceGrid::Index ChoiceGrid::best(bool smooth) const {
  if (m_cost.empty()) throw InvalidArgument("choice grid: no choices to pick from");
  Index best;
  double least = INFINITY;
  for (std::size_t o = 0; o < m_outer; ++o)
    for (std::size_t k = 0; k < m_keeps; ++k)
      for (std::size_t a = 0; a < m_adds; ++a)
        if (const double c = smooth ? neighbourhoodCost(o, k, a) : cost(o, k, a); c < least) {
          least = c;
          best = {o, k, a};
        }
  return best;
}

}  // namespace sagrid
