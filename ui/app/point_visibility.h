// Whether the surface hides an affordance point from the eye (the viewport dims the labels of
// hidden points, so a row of knobs seen from one side shows the near labels clearly).
#pragma once

#include <Eigen/Core>

namespace sagrid::ui {

class AnnotationDocument;

// True where the ray from `eye` (z-up view frame) towards point `index` meets the surface clearly
// before the point itself.
bool pointHiddenFromEye(const AnnotationDocument& doc, const Eigen::Vector3f& eye, int index);

}  // namespace sagrid::ui
