#include "core/generate/wall_fixtures.h"

#include <gtest/gtest.h>

#include <set>

#include "core/common/error.h"
#include "core/generate/dataset_generator.h"

namespace sagrid::gen {
namespace {

const GeneratorOptions kAlways{1.0};

TEST(WallFixtures, ZeroShareWritesTheBenchLookUnchanged) {
  for (int i = 0; i < 6; ++i) {
    const FinishedObject plain = makeObject("sink", 31, i, MeshFormat::Obj);
    const FinishedObject zero = makeObject("sink", 31, i, MeshFormat::Obj, GeneratorOptions{0.0});
    EXPECT_EQ(plain.mesh.positions, zero.mesh.positions);
    EXPECT_EQ(plain.mesh.triangles, zero.mesh.triangles);
    EXPECT_FALSE(zero.labels.object.extra["generator"].contains("wall_fixtures"));
  }
}

TEST(WallFixtures, PartsAreAddedOutsideTheSinkAndLeaveItsPointsAlone) {
  int dressed = 0;
  for (int i = 0; i < 40; ++i) {
    const GeneratedObject bare = makeRawObject("sink", 32, i);
    const GeneratedObject object = makeRawObject("sink", 32, i, kAlways);
    ASSERT_EQ(object.points.size(), bare.points.size());
    for (std::size_t p = 0; p < bare.points.size(); ++p)
      EXPECT_EQ(object.points[p].position, bare.points[p].position);
    if (!acceptsWallFixtures(bare)) {
      EXPECT_EQ(object.mesh.triangles.size(), bare.mesh.triangles.size()) << "bare faucet " << i;
      continue;
    }
    ++dressed;
    ASSERT_GT(object.mesh.triangles.size(), bare.mesh.triangles.size());
    // The sink's own triangles come first, unchanged.
    for (std::size_t t = 0; t < bare.mesh.triangles.size(); ++t)
      ASSERT_EQ(object.mesh.triangles[t], bare.mesh.triangles[t]);
    // Every added vertex lies outside the sink's bounding box (behind, above, in front or beside).
    Eigen::AlignedBox3f inside = bare.mesh.bounds();
    inside.min().array() += 1e-4f;
    inside.max().array() -= 1e-4f;
    for (std::size_t v = bare.mesh.positions.size(); v < object.mesh.positions.size(); ++v) {
      ASSERT_FALSE(inside.contains(object.mesh.positions[v])) << "object " << i << " vertex " << v;
    }
    const auto names = object.generator.at("wall_fixtures").get<std::vector<std::string>>();
    EXPECT_FALSE(names.empty());
  }
  EXPECT_GT(dressed, 20);
}

TEST(WallFixtures, EachKindOfFixtureIsDrawnAndTheShareIsHonoured) {
  std::set<std::string> seen;
  int dressed = 0, eligible = 0;
  for (int i = 0; i < 200; ++i) {
    const GeneratedObject object = makeRawObject("sink", 33, i, GeneratorOptions{0.5});
    if (!acceptsWallFixtures(object)) continue;
    ++eligible;
    if (!object.generator.contains("wall_fixtures")) continue;
    ++dressed;
    for (const auto& n : object.generator.at("wall_fixtures")) seen.insert(n.get<std::string>());
  }
  for (const char* name : {"mirror", "framed_mirror", "mirror_cabinet", "mirror_pair", "light_bar",
                           "wall_lamps", "shelf", "back_panel", "towel_bar"}) {
    EXPECT_TRUE(seen.count(name)) << name;
  }
  EXPECT_NEAR(static_cast<double>(dressed) / eligible, 0.5, 0.12);
}

TEST(WallFixtures, StovesAndDistractorsAreNotDressedAndABadShareIsRefused) {
  const GeneratedObject stove = makeRawObject("stove", 34, 0, kAlways);
  EXPECT_EQ(stove.mesh.triangles.size(), makeRawObject("stove", 34, 0).mesh.triangles.size());
  EXPECT_FALSE(stove.generator.contains("wall_fixtures"));
  EXPECT_THROW(makeRawObject("sink", 34, 0, GeneratorOptions{1.5}), InvalidArgument);
  EXPECT_THROW(makeRawObject("sink", 34, 0, GeneratorOptions{-0.1}), InvalidArgument);
}

}  // namespace
}  // namespace sagrid::gen
