// Knobs paired with burners by layout: the knob row left to right onto the burners column by
// column from the left, front before rear.
#include "core/controls/control_pairing.h"

#include <gtest/gtest.h>

namespace sagrid {
namespace {

TEST(ControlPairing, AKnobRowMapsOntoTwoColumnsFrontFirst) {
  // Burners: rear left, front left, rear right, front right (front is -y).
  const std::vector<Eigen::Vector2f> burners{{-0.15f, 0.1f}, {-0.15f, -0.1f}, {0.15f, 0.1f}, {0.15f, -0.1f}};
  // Knobs given out of order along x.
  const std::vector<Eigen::Vector2f> knobs{{0.1f, -0.3f}, {-0.2f, -0.3f}, {0.2f, -0.3f}, {-0.1f, -0.3f}};
  EXPECT_EQ(pairKnobsWithBurners(knobs, burners), (std::vector<int>{3, 1, 2, 0}));
}

TEST(ControlPairing, ExtraKnobsDriveNothingAndExtraBurnersStayUnpaired) {
  const std::vector<Eigen::Vector2f> burners{{-0.1f, 0.0f}, {0.1f, 0.0f}};
  EXPECT_EQ(pairKnobsWithBurners({{-0.2f, -0.3f}, {0.0f, -0.3f}, {0.2f, -0.3f}}, burners),
            (std::vector<int>{0, 1, -1}));
  EXPECT_EQ(pairKnobsWithBurners({{0.3f, -0.3f}}, burners), (std::vector<int>{0}));
  EXPECT_TRUE(pairKnobsWithBurners({}, burners).empty());
  EXPECT_EQ(pairKnobsWithBurners({{0, 0}}, {}), (std::vector<int>{-1}));
}

}  // namespace
}  // namespace sagrid
