#include "core/features/printed_marks.h"

#include <gtest/gtest.h>

#include <random>

#include "core/generate/dataset_generator.h"
#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

const gen::GeneratorOptions kGlassHobs{0.0, 1.0};

float nearest(const Eigen::Vector3f& p, const std::vector<Eigen::Vector3f>& others) {
  float best = 1e9f;
  for (const auto& o : others) best = std::min(best, (p - o).norm());
  return best;
}

std::vector<Eigen::Vector3f> truthOf(const gen::GeneratedObject& object, const std::string& type) {
  std::vector<Eigen::Vector3f> out;
  for (const auto& p : object.points)
    if (p.type == type) out.push_back(p.position);
  return out;
}

std::vector<Eigen::Vector3f> centres(const std::vector<PrintedCircle>& circles) {
  std::vector<Eigen::Vector3f> out;
  for (const auto& c : circles) out.push_back(c.centre);
  return out;
}

TEST(PrintedMarks, GlassHobZonesAndRoundTouchSymbolsAreFoundWhereTheyArePrinted) {
  int zones = 0, zonesFound = 0, zonesFalse = 0, symbolsFound = 0, symbolsFalse = 0;
  for (int i = 0; i < 16; ++i) {
    const gen::GeneratedObject hob = gen::makeRawObject("stove", 51, i, kGlassHobs);
    const PrintedMarks marks = findPrintedMarks(hob.mesh);
    const auto heat = truthOf(hob, "heatsource"), toggles = truthOf(hob, "togglebutton");
    zones += static_cast<int>(heat.size());
    for (const auto& h : heat) zonesFound += nearest(h, centres(marks.zones)) < 0.015f;
    for (const auto& z : marks.zones) {
      zonesFalse += nearest(z.centre, heat) > 0.02f;
      EXPECT_NEAR(z.centre.z(), hob.mesh.bounds().max().z(), 0.003f) << "on the glass, hob " << i;
    }
    for (const auto& s : marks.symbols) {
      const bool right = nearest(s.centre, toggles) < 0.01f;
      symbolsFound += right;
      symbolsFalse += !right;
    }
  }
  EXPECT_GE(zonesFound, zones * 9 / 10) << zonesFound << " of " << zones;
  EXPECT_LE(zonesFalse, zones / 10);
  // Plus/minus marks are not circles; the round ones are found, and hardly anything else.
  EXPECT_GT(symbolsFound, 40);
  EXPECT_LE(symbolsFalse, symbolsFound / 10);
}

TEST(PrintedMarks, NothingOnStovesWhoseBurnersAreGeometryOrOnPlainAndNoisyTops) {
  for (int i = 0; i < 30; ++i) {
    const gen::GeneratedObject stove = gen::makeRawObject("stove", 52, i);
    if (stove.generator.at("burner_look") == "glass_zone") continue;
    EXPECT_TRUE(findPrintedMarks(stove.mesh).empty()) << i;
  }
  EXPECT_TRUE(findPrintedMarks(test::box({0, 0, 0}, {0.6f, 0.5f, 0.01f})).empty());

  // A worktop with a photographic-looking noise texture: edges everywhere, circles nowhere.
  Mesh top = test::quadZ({0, 0}, {0.6f, 0.5f}, 0.9f);
  Texture noise;
  noise.width = noise.height = 256;
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int p = 0; p < 256 * 256; ++p) {
    const auto v = static_cast<std::uint8_t>(byte(rng));
    noise.rgba.insert(noise.rgba.end(), {v, v, v, 255});
  }
  top.textures = {noise};
  top.materials = {Material{"granite", Eigen::Vector3f::Ones(), 0}};
  top.triangleMaterials.assign(top.triangles.size(), 0);

  EXPECT_TRUE(findPrintedMarks(top).empty());
}

// The 2-zone hob of the real corpus: plus and minus keys printed as filled discs in a row, a
// line drawn just below them. The line crosses the ring outside each disc that tells a symbol from
// a noisy texture; it must not hide the keys.
TEST(PrintedMarks, TouchKeysAboveAPrintedLineAreFound) {
  Mesh glass = test::quadZ({0, 0}, {0.6f, 0.6f}, 0.9f);
  Texture print;
  print.width = print.height = 512;
  print.rgba.assign(512 * 512 * 4, 255);
  const std::vector<int> keyColumns = {150, 190, 320, 360};
  const int row = 256, radius = 6;
  for (int y = 0; y < 512; ++y)
    for (int x = 0; x < 512; ++x) {
      bool white = (y == row + 8 || y == row + 9) && x >= 120 && x <= 390;
      for (int c : keyColumns)
        white = white || (x - c) * (x - c) + (y - row) * (y - row) <= radius * radius;
      for (int k = 0; k < 3; ++k)
        print.rgba[(static_cast<std::size_t>(y) * 512 + x) * 4 + k] = white ? 240 : 20;
    }
  glass.textures = {print};
  glass.materials = {Material{"glass", Eigen::Vector3f::Ones(), 0}};
  glass.triangleMaterials.assign(glass.triangles.size(), 0);

  const PrintedMarks marks = findPrintedMarks(glass);
  ASSERT_EQ(marks.symbols.size(), keyColumns.size());
  std::vector<Eigen::Vector3f> keys;
  for (int c : keyColumns) keys.emplace_back((c + 0.5f) / 512.0f * 0.6f, 0.3f, 0.9f);
  for (const auto& s : marks.symbols) EXPECT_LT(nearest(s.centre, keys), 0.006f);
  EXPECT_TRUE(marks.zones.empty());
}

TEST(PrintedMarks, OnlyUpwardFacingTexturedSurfacesAreRead) {
  gen::GeneratedObject hob = gen::makeRawObject("stove", 51, 0, kGlassHobs);
  ASSERT_FALSE(findPrintedMarks(hob.mesh).empty());
  // Turned on its side, the printed glass faces +y: no top, no marks.
  for (auto& p : hob.mesh.positions) p = Eigen::Vector3f(p.x(), -p.z(), p.y());
  EXPECT_TRUE(findPrintedMarks(hob.mesh).empty());
}

}  // namespace
}  // namespace sagrid
