#include "ui/document/point_row.h"

#include <limits>

#include "core/geometry/surface_scene.h"
#include "ui/document/annotation_document.h"
#include "ui/document/point_copies.h"

namespace sagrid::ui {

std::optional<AffordancePoint> nextPointInRow(const AnnotationDocument& document, int index) {
  return nextPointInRow(document, document.points(), index);
}

std::optional<AffordancePoint> nextPointInRow(const AnnotationDocument& document,
                                              const std::vector<AffordancePoint>& points,
                                              int index) {
  if (index < 0 || index >= static_cast<int>(points.size())) return std::nullopt;
  const AffordancePoint& from = points[std::size_t(index)];
  const Eigen::Vector3f at = document.toView(from.position);
  float nearest = std::numeric_limits<float>::infinity();
  Eigen::Vector3f step = Eigen::Vector3f::Zero();
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    if (i == index || points[std::size_t(i)].type != from.type) continue;
    const Eigen::Vector3f offset = at - document.toView(points[std::size_t(i)].position);
    if (offset.norm() > 0 && offset.norm() < nearest) {
      nearest = offset.norm();
      step = offset;
    }
  }
  if (!(nearest < std::numeric_limits<float>::infinity())) return std::nullopt;
  const ClosestPoint onSurface = document.surface().closestPoint(at + step);
  if (onSurface.triangle < 0 || onSurface.distance > kRowOffSurface * nearest) return std::nullopt;
  for (const AffordancePoint& q : points)
    if (q.type == from.type &&
        (document.toView(q.position) - onSurface.position).norm() < kCopyTaken * nearest)
      return std::nullopt;
  AffordancePoint next;
  next.type = from.type;
  next.position = document.toFile(onSurface.position);
  next.normal = document.toFile(onSurface.normal).normalized();
  return next;
}

}  // namespace sagrid::ui
