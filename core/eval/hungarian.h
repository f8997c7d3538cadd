// Minimum-cost assignment (Hungarian method, O(n^2 m) with potentials) for matching predicted
// affordance points to ground-truth instances in the evaluation.
#pragma once

#include <vector>

namespace sagrid {

// `cost` is rows x cols (rectangular allowed, every row the same length). Returns, for each row,
// the matched column or -1 (when rows > cols, rows - cols rows stay unmatched). The total cost of
// the min(rows, cols) matched pairs is minimal. Throws InvalidArgument on ragged or non-finite
// input.
std::vector<int> hungarianAssignment(const std::vector<std::vector<double>>& cost);

}  // namespace sagrid
