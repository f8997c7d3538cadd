#include "ui/app/point_visibility.h"

#include <algorithm>

#include "core/geometry/surface_scene.h"
#include "ui/document/annotation_document.h"

namespace sagrid::ui {

bool pointHiddenFromEye(const AnnotationDocument& doc, const Eigen::Vector3f& eye, int index) {
  const Eigen::Vector3f point = doc.pointInView(index);
  const Eigen::Vector3f towards = point - eye;
  const float distance = towards.norm();
  if (!(distance > 0)) return false;
  // A point lies on the surface: the ray meets it there. Hidden only where something is in front
  // by more than a hundredth of the way (and of the object's size), not by rounding.
  const float margin = std::max(0.01f * distance, 0.005f * doc.mesh().bounds().diagonal().norm());
  return distance > margin && doc.surface().occluded(eye, towards / distance, 0.0f, distance - margin);
}

}  // namespace sagrid::ui
