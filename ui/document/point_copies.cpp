#include "ui/document/point_copies.h"

#include <algorithm>

#include "core/geometry/points_on_copies.h"
#include "ui/document/annotation_document.h"

namespace sagrid::ui {

std::vector<AffordancePoint> pointsForCopies(const AnnotationDocument& document,
                                             const AffordancePoint& source) {
  const Eigen::Vector3f from = document.toView(source.position);
  std::vector<AffordancePoint> out;
  for (const Eigen::Vector3f& to : pointsOnCopies(document.mesh(), from)) {
    const float near = kCopyTaken * (to - from).norm();
    const auto& points = document.points();
    const bool taken = std::any_of(points.begin(), points.end(), [&](const AffordancePoint& q) {
      return q.type == source.type && (document.toView(q.position) - to).norm() < near;
    });
    if (taken) continue;
    AffordancePoint point = source;
    point.position = document.toFile(to);
    out.push_back(std::move(point));
  }
  return out;
}

}  // namespace sagrid::ui
