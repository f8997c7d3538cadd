// The viewport dims the labels of points the surface hides from the eye (seen curating in the
// window: the labels of a row of knobs and of points behind the object piled on the near ones).
#include "ui/app/point_visibility.h"

#include <gtest/gtest.h>

#include <memory>

#include "support/analytic_meshes.h"
#include "ui/document/annotation_document.h"

namespace sagrid::ui {
namespace {

AffordancePoint at(const Eigen::Vector3f& position) {
  AffordancePoint p;
  p.type = "togglebutton";
  p.position = position;
  return p;
}

TEST(PointVisibility, APointBehindTheSurfaceIsHiddenAndOneFacingTheEyeIsNot) {
  ObjectLabels labels;
  labels.affordances = {at({0.5f, 0.5f, 1.0f}), at({0.5f, 0.5f, 0.0f}), at({1.0f, 0.5f, 0.5f})};
  const AnnotationDocument doc(
      std::make_shared<Mesh>(sagrid::test::box({0, 0, 0}, {1, 1, 1})), labels, "");
  const Eigen::Vector3f above(0.5f, 0.5f, 5.0f);
  EXPECT_FALSE(pointHiddenFromEye(doc, above, 0));  // on the top face, seen from above
  EXPECT_TRUE(pointHiddenFromEye(doc, above, 1));   // on the bottom face, behind the box
  EXPECT_TRUE(pointHiddenFromEye(doc, above, 2));   // on a side, behind the top's edge
  const Eigen::Vector3f side(5.0f, 0.5f, 0.5f);
  EXPECT_FALSE(pointHiddenFromEye(doc, side, 2));
  EXPECT_TRUE(pointHiddenFromEye(doc, side, 1));  // the bottom's centre, from level with the box
}

}  // namespace
}  // namespace sagrid::ui
