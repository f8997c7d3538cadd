#include "core/annotate/touch_keys_pass.h"

#include <gtest/gtest.h>

#include "core/annotate/repeated_parts_pass.h"
#include "core/generate/dataset_generator.h"
#include "core/geometry/surface_scene.h"
#include "core/grid/normalization.h"

namespace sagrid {
namespace {

constexpr int kResolution = 64;

std::vector<PrintedCircle> keysOf(const Mesh& mesh, const std::string& category) {
  const Normalization n = Normalization::fromMesh(mesh);
  const SurfaceScene scene(mesh);
  return touchKeysOf(category, normalizedParts(mesh, n), scene, n, kResolution);
}

// Generated stoves with touch controls: a key on every toggle button, within half a centimetre of
// its ground-truth point (the middle of the pad's top). The network alone found 2 of 22 such
// stoves' pads (150 stoves of seed 9501).
TEST(TouchKeysPass, EveryTouchControlOfAGeneratedStoveIsAKey) {
  int touchStoves = 0;
  for (int i = 0; i < 60 && touchStoves < 4; ++i) {
    const gen::GeneratedObject stove = gen::makeRawObject("stove", 9502, i);
    if (stove.generator.value("controls", "") != "touch") continue;
    ++touchStoves;
    const auto keys = keysOf(stove.mesh, "stove");
    std::vector<Eigen::Vector3f> buttons;
    for (const auto& p : stove.points)
      if (p.type == "togglebutton") buttons.push_back(p.position);
    ASSERT_EQ(keys.size(), buttons.size()) << "stove " << i << " " << stove.generator.dump();
    for (const Eigen::Vector3f& b : buttons) {
      float nearest = 1e9f;
      for (const PrintedCircle& k : keys) nearest = std::min(nearest, (k.centre - b).norm());
      EXPECT_LT(nearest, 0.005f) << "stove " << i;
    }
  }
  EXPECT_GE(touchStoves, 2);
}

TEST(TouchKeysPass, KeysAreAStovesToggleButtonsOnly) {
  int touchStoves = 0;
  for (int i = 0; i < 60; ++i) {
    const gen::GeneratedObject stove = gen::makeRawObject("stove", 9502, i);
    if (stove.generator.value("controls", "") != "touch") continue;
    ++touchStoves;
    EXPECT_TRUE(keysOf(stove.mesh, "sink").empty());
    const auto keys = keysOf(stove.mesh, "stove");
    EXPECT_EQ(touchKeysFor(keys, "togglebutton").circles.size(), keys.size());
    EXPECT_TRUE(touchKeysFor(keys, "togglebutton").replaceModelPoints);
    EXPECT_TRUE(touchKeysFor(keys, "heatsource").circles.empty());
    break;
  }
  EXPECT_EQ(touchStoves, 1);
  EXPECT_TRUE(touchKeysFor({}, "togglebutton").circles.empty());
}

}  // namespace
}  // namespace sagrid
