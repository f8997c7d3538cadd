#include "core/features/printed_marks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
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
// A 0.6 m glass top at height 0.9 printed dark (512 x 512 pixels), white where `white(x, y)`.
Mesh printedGlass(const std::function<bool(int, int)>& white) {
  Mesh glass = test::quadZ({0, 0}, {0.6f, 0.6f}, 0.9f);
  Texture print;
  print.width = print.height = 512;
  print.rgba.assign(512 * 512 * 4, 255);
  for (int y = 0; y < 512; ++y)
    for (int x = 0; x < 512; ++x)
      for (int k = 0; k < 3; ++k)
        print.rgba[(static_cast<std::size_t>(y) * 512 + x) * 4 + k] = white(x, y) ? 240 : 20;
  glass.textures = {print};
  glass.materials = {Material{"glass", Eigen::Vector3f::Ones(), 0}};
  glass.triangleMaterials.assign(glass.triangles.size(), 0);
  return glass;
}

bool onKey(const std::vector<std::pair<int, int>>& keys, int x, int y) {
  const int radius = 6;
  return std::any_of(keys.begin(), keys.end(), [&](const auto& k) {
    return (x - k.first) * (x - k.first) + (y - k.second) * (y - k.second) <= radius * radius;
  });
}

// The glass printed with white round keys (radius 6 pixels) at `keys` (pixel column, row), and
// a white line under the row at `lineRow` when it is positive.
Mesh glassWithKeys(const std::vector<std::pair<int, int>>& keys, int lineRow) {
  return printedGlass([&](int x, int y) {
    const bool line = lineRow > 0 && (y == lineRow + 8 || y == lineRow + 9) && x >= 120 && x <= 390;
    return line || onKey(keys, x, y);
  });
}

// Where a pixel of glassWithKeys's print lies on the glass (texture rows run from the far edge).
Eigen::Vector3f onGlass(const std::pair<int, int>& pixel) {
  return {(pixel.first + 0.5f) / 512.0f * 0.6f, (1.0f - (pixel.second + 0.5f) / 512.0f) * 0.6f,
          0.9f};
}

TEST(PrintedMarks, TouchKeysAboveAPrintedLineAreFound) {
  const std::vector<std::pair<int, int>> keyPixels = {
      {150, 256}, {190, 256}, {320, 256}, {360, 256}};
  const PrintedMarks marks = findPrintedMarks(glassWithKeys(keyPixels, 256));
  ASSERT_EQ(marks.symbols.size(), keyPixels.size());
  std::vector<Eigen::Vector3f> keys;
  for (const auto& k : keyPixels) keys.push_back(onGlass(k));
  for (const auto& s : marks.symbols) EXPECT_LT(nearest(s.centre, keys), 0.006f);
  EXPECT_TRUE(marks.zones.empty());
}

TEST(PrintedMarks, ASymbolFarFromTheOthersIsNoTouchKey) {
  // Four keys 40 pixels apart in a row, and one more round mark 300 pixels away (a sign at the
  // back of the hob).
  const std::vector<std::pair<int, int>> keyPixels = {
      {150, 400}, {190, 400}, {230, 400}, {270, 400}, {256, 100}};
  const Mesh glass = glassWithKeys(keyPixels, 0);
  const PrintedMarks marks = findPrintedMarks(glass);
  ASSERT_EQ(marks.symbols.size(), 4u);
  for (const auto& s : marks.symbols) EXPECT_GT(nearest(s.centre, {onGlass(keyPixels[4])}), 0.1f);
  PrintedMarkSettings keepAll;
  keepAll.isolatedSymbolSpacings = 0;
  EXPECT_EQ(findPrintedMarks(glass, keepAll).symbols.size(), 5u);
}

// Both real induction hobs have one key printed as an oval outline beside their round keys.
TEST(PrintedMarks, AnOvalKeyIsFoundAtItsCentre) {
  const std::vector<std::pair<int, int>> keyPixels = {{150, 400}, {190, 400}, {230, 400}};
  // An outline 2 pixels wide, 8 pixels from the segment between (175, 360) and (205, 360), and
  // two round outlines as wide side by side (two keys, no oval between them).
  const auto outline = [](int x, int y, float ax, float bx, float row) {
    const float t = std::clamp((static_cast<float>(x) - ax) / (bx - ax), 0.0f, 1.0f);
    const float d =
        std::hypot(static_cast<float>(x) - (ax + t * (bx - ax)), static_cast<float>(y) - row);
    return d >= 7.0f && d <= 9.0f;
  };
  const Mesh glass = printedGlass([&](int x, int y) {
    return onKey(keyPixels, x, y) || outline(x, y, 175, 205, 360) || outline(x, y, 300, 300, 360) ||
           outline(x, y, 320, 320, 360);
  });
  const PrintedMarks marks = findPrintedMarks(glass);
  ASSERT_EQ(marks.symbols.size(), 6u);
  std::vector<Eigen::Vector3f> expected;
  for (const auto& k : keyPixels) expected.push_back(onGlass(k));
  for (int column : {300, 320}) expected.push_back(onGlass({column, 360}));
  const Eigen::Vector3f ovalCentre = onGlass({190, 360});
  int ovals = 0;
  for (const auto& s : marks.symbols) {
    if ((s.centre - ovalCentre).norm() < 0.006f) {
      ++ovals;
      EXPECT_NEAR(s.radius, 23.0f / 512 * 0.6f, 0.004f) << "half its length";
      continue;
    }
    EXPECT_LT(nearest(s.centre, expected), 0.006f);
  }
  EXPECT_EQ(ovals, 1);

  PrintedMarkSettings roundOnly;
  roundOnly.ovals.maxLength = 0;
  const PrintedMarks round = findPrintedMarks(glass, roundOnly);
  EXPECT_EQ(round.symbols.size(), 5u);
  for (const auto& s : round.symbols) EXPECT_GT((s.centre - ovalCentre).norm(), 0.01f);
}

TEST(PrintedMarks, SymbolsStandingTogetherKeepsRowsAndGroupsAndFewSymbols) {
  const auto at = [](float x, float y) { return PrintedCircle{{x, y, 0.9f}, 0.005f, 1.0f}; };
  // Two groups of two, 0.3 apart: every symbol has a neighbour 0.03 away.
  const std::vector<PrintedCircle> groups = {at(0.1f, 0.1f), at(0.13f, 0.1f), at(0.4f, 0.1f),
                                             at(0.43f, 0.1f)};
  EXPECT_EQ(symbolsStandingTogether(groups, 2.5f).size(), 4u);
  // Two symbols far apart: too few to tell which one stands alone.
  EXPECT_EQ(symbolsStandingTogether({at(0.1f, 0.1f), at(0.5f, 0.5f)}, 2.5f).size(), 2u);
  // Two close and one far: the far one goes, the order of the others stays.
  const auto kept =
      symbolsStandingTogether({at(0.1f, 0.1f), at(0.5f, 0.5f), at(0.12f, 0.1f)}, 2.5f);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_FLOAT_EQ(kept[0].centre.x(), 0.1f);
  EXPECT_FLOAT_EQ(kept[1].centre.x(), 0.12f);
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
