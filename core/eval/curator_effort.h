// What a curator must do to make one object's predicted points right, counted the way the GUI
// works: every predicted point farther than the match radius from its Hungarian-matched ground
// truth is dragged (one edit), every extra prediction is deleted (one edit), every missing point is
// added (one edit). Placing every point by hand costs one edit per ground-truth point, so the ratio
// of the two says whether the predictions save work; an object with no edit is right "with one
// key" (accept).
#pragma once

#include <cstddef>

#include "core/eval/metrics.h"

namespace sagrid {

struct PointEdits {
  std::size_t drags = 0, deletions = 0, additions = 0;
  std::size_t handPoints = 0;  // ground-truth points: the by-hand cost
  std::size_t total() const { return drags + deletions + additions; }
};

// Edits for one type of one object from its match (see matchPoints).
PointEdits pointEdits(const ObjectMatch& match);

struct CuratorEffort {
  std::size_t objects = 0;
  double editsPerObject = 0;       // mean over objects of the summed edits of all their types
  double handPointsPerObject = 0;  // mean ground-truth points per object
  double oneKeyShare = 0;          // share of objects needing no edit
  double dragsPerObject = 0, deletionsPerObject = 0, additionsPerObject = 0;
};

// Accumulates whole objects: call addObject once per object with the edits of all its types.
class CuratorEffortAccumulator {
 public:
  void addObject(const PointEdits& edits);
  CuratorEffort result() const;

 private:
  std::size_t m_objects = 0, m_oneKey = 0;
  PointEdits m_sum;
};

PointEdits& operator+=(PointEdits& a, const PointEdits& b);

}  // namespace sagrid
