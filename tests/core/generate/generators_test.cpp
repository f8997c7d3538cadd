// Ground truth on the surface, parameter ranges reached, sizes, for many seeds of both generators.
#include <algorithm>
#include <map>
#include <set>

#include <limits>

#include <gtest/gtest.h>

#include "core/generate/dataset_generator.h"
#include "core/generate/sink_generator.h"
#include "core/generate/stove_generator.h"
#include "core/geometry/closest_point_on_triangle.h"
#include "support/analytic_meshes.h"

namespace sagrid::gen {
namespace {

using test::bruteForceDistance;

// Every affordance of every object lies within 1 cm (in metres) of the merged mesh, in the frame
// the labels are written in (file units, file up axis), after all realism transforms.
void expectGroundTruthOnSurface(const std::string& category, int count, std::uint64_t seed) {
  float worst = 0;
  for (int i = 0; i < count; ++i) {
    const FinishedObject object = makeObject(category, seed, i, MeshFormat::Mixed);
    ASSERT_FALSE(object.labels.affordances.empty()) << object.id;
    for (const auto& a : object.labels.affordances) {
      const Eigen::Vector3f zup = fileToZUp(a.position, object.mesh.fileUp);
      const float metres = bruteForceDistance(object.mesh, zup) * static_cast<float>(object.metersPerUnit);
      worst = std::max(worst, metres);
      EXPECT_LE(metres, 0.01f) << object.id << " " << a.type;
    }
  }
  ::testing::Test::RecordProperty("worst_distance_mm_" + category, std::to_string(worst * 1000.0f));
}

TEST(Generators, StoveGroundTruthWithinOneCentimetreOfSurfaceSlow) { expectGroundTruthOnSurface("stove", 200, 11); }
TEST(Generators, SinkGroundTruthWithinOneCentimetreOfSurfaceSlow) { expectGroundTruthOnSurface("sink", 200, 12); }

TEST(Generators, StoveCountsMatchParametersAndEveryRangeIsReached) {
  std::map<std::string, std::set<std::string>> seen;
  std::size_t maxTriangles = 0, minTriangles = 1u << 30;
  std::set<int> burnerCounts;
  float minWidth = 10, maxWidth = 0;
  for (int i = 0; i < 300; ++i) {
    const GeneratedObject o = makeRawObject("stove", 3, i);
    const auto& g = o.generator;
    for (const char* f : {"kind", "layout", "burner_look", "controls", "knob_style", "finish"}) {
      seen[f].insert(g[f].get<std::string>());
    }
    int heat = 0, toggle = 0;
    for (const auto& p : o.points) {
      heat += p.type == "heatsource";
      toggle += p.type == "togglebutton";
    }
    EXPECT_EQ(heat, g["burners"].get<int>());
    EXPECT_EQ(toggle, g["knobs"].get<int>());
    EXPECT_GE(toggle, heat);  // a knob per burner, or more
    burnerCounts.insert(heat);
    minWidth = std::min(minWidth, g["width_m"].get<float>());
    maxWidth = std::max(maxWidth, g["width_m"].get<float>());
    maxTriangles = std::max(maxTriangles, o.mesh.triangleCount());
    minTriangles = std::min(minTriangles, o.mesh.triangleCount());
  }
  auto all = [](const std::vector<std::string>& v) { return std::set<std::string>(v.begin(), v.end()); };
  EXPECT_EQ(seen["kind"], all(stoveKinds()));
  EXPECT_EQ(seen["layout"], all(stoveLayouts()));
  EXPECT_EQ(seen["burner_look"], all(stoveBurnerLooks()));
  EXPECT_EQ(seen["controls"], all(stoveControlPlacements()));
  EXPECT_GE(seen["knob_style"].size(), 7u);  // 7 knob shapes + touch
  EXPECT_GE(seen["finish"].size(), 6u);
  EXPECT_EQ(burnerCounts, (std::set<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_LT(minWidth, 0.31f);
  EXPECT_GT(maxWidth, 1.0f);
  EXPECT_LE(maxTriangles, 80000u);
  EXPECT_GE(minTriangles, 100u);
}

TEST(Generators, SinkCountsMatchParametersAndEveryRangeIsReached) {
  std::map<std::string, std::set<std::string>> seen;
  std::size_t maxTriangles = 0;
  for (int i = 0; i < 300; ++i) {
    const GeneratedObject o = makeRawObject("sink", 4, i);
    const auto& g = o.generator;
    for (const char* f : {"kind", "basin_shape", "faucet", "handle", "finish"}) seen[f].insert(g[f].get<std::string>());
    for (const auto& d : g["distractors"]) seen["distractors"].insert(d.get<std::string>());
    seen["basins"].insert(std::to_string(g["basins"].get<int>()));
    int fluid = 0, toggle = 0;
    for (const auto& p : o.points) {
      fluid += p.type == "fluidsource";
      toggle += p.type == "togglebutton";
    }
    const std::string handle = g["handle"];
    EXPECT_EQ(toggle, handle.rfind("twin", 0) == 0 ? 2 : 1) << i << " " << handle;
    const bool spoutless = g["faucet"] == "arm_metaworld" && !g["spout"].get<bool>();
    EXPECT_EQ(fluid, spoutless ? 0 : 1) << i;
    if (g["kind"] == "bare_faucet") {
      EXPECT_EQ(g["basins"].get<int>(), 0);
    }
    maxTriangles = std::max(maxTriangles, o.mesh.triangleCount());
  }
  auto all = [](const std::vector<std::string>& v) { return std::set<std::string>(v.begin(), v.end()); };
  EXPECT_EQ(seen["kind"], all(sinkKinds()));
  EXPECT_EQ(seen["faucet"], all(faucetTypes()));
  EXPECT_EQ(seen["handle"], all(faucetHandleTypes()));
  EXPECT_EQ(seen["basin_shape"], (std::set<std::string>{"none", "rectangular", "round"}));
  EXPECT_EQ(seen["basins"], (std::set<std::string>{"0", "1", "2"}));
  EXPECT_TRUE(seen["distractors"].count("soap_dispenser"));
  EXPECT_TRUE(seen["distractors"].count("side_sprayer"));
  EXPECT_LE(maxTriangles, 80000u);
}

TEST(Generators, RealismVariesUnitsUpAxisAndColours) {
  std::set<std::string> units, ups, colours;
  for (int i = 0; i < 60; ++i) {
    const FinishedObject o = makeObject(i % 2 ? "stove" : "sink", 9, i, MeshFormat::Mixed);
    units.insert(o.labels.object.extra["units"].get<std::string>());
    ups.insert(o.labels.object.up);
    colours.insert(o.labels.object.extra["generator"]["realism"]["colors"].get<std::string>());
    EXPECT_EQ(o.mesh.fileUp == UpAxis::Y, o.meshFileName == "mesh.glb");
  }
  EXPECT_EQ(units, (std::set<std::string>{"m", "cm", "mm", "in"}));
  EXPECT_EQ(ups, (std::set<std::string>{"y", "z"}));
  EXPECT_EQ(colours, (std::set<std::string>{"material", "vertex"}));
}

}  // namespace
}  // namespace sagrid::gen
