#include "core/eval/curator_effort.h"

#include <algorithm>
#include <limits>

namespace sagrid {

PointEdits pointEdits(const ObjectMatch& match) {
  PointEdits e;
  const std::size_t paired = std::min(match.predicted, match.truth);
  e.drags = paired - std::min(paired, match.truePositives);
  e.deletions = match.predicted - paired;
  e.additions = match.truth - paired;
  e.handPoints = match.truth;
  return e;
}

PointEdits& operator+=(PointEdits& a, const PointEdits& b) {
  a.drags += b.drags;
  a.deletions += b.deletions;
  a.additions += b.additions;
  a.handPoints += b.handPoints;
  return a;
}

void CuratorEffortAccumulator::addObject(const PointEdits& edits) {
  ++m_objects;
  m_oneKey += edits.total() == 0;
  m_sum += edits;
}

CuratorEffort CuratorEffortAccumulator::result() const {
  CuratorEffort r;
  r.objects = m_objects;
  if (m_objects == 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    r.editsPerObject = r.handPointsPerObject = r.oneKeyShare = nan;
    r.dragsPerObject = r.deletionsPerObject = r.additionsPerObject = nan;
    return r;
  }
  const double n = static_cast<double>(m_objects);
  r.editsPerObject = static_cast<double>(m_sum.total()) / n;
  r.handPointsPerObject = static_cast<double>(m_sum.handPoints) / n;
  r.oneKeyShare = static_cast<double>(m_oneKey) / n;
  r.dragsPerObject = static_cast<double>(m_sum.drags) / n;
  r.deletionsPerObject = static_cast<double>(m_sum.deletions) / n;
  r.additionsPerObject = static_cast<double>(m_sum.additions) / n;
  return r;
}

}  // namespace sagrid
