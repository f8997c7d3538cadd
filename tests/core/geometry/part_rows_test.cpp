#include "core/geometry/part_rows.h"

#include <gtest/gtest.h>

#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"

namespace sagrid {
namespace {

// Unit boxes (scaled by `scales`, 1 where not given) centred at `centres`.
std::vector<ConnectedPart> boxesAt(const std::vector<Eigen::Vector3f>& centres,
                                   const std::vector<float>& scales = {}) {
  Mesh mesh;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const float half = 0.5f * (i < scales.size() ? scales[i] : 1.0f);
    test::append(mesh, test::box(centres[i] - Eigen::Vector3f::Constant(half),
                                 centres[i] + Eigen::Vector3f::Constant(half)));
  }
  return connectedParts(mesh);
}

// The parts' indices in connectedParts' order (equal triangle counts keep the mesh's order).
std::vector<std::size_t> firstParts(std::size_t n) {
  std::vector<std::size_t> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = i;
  return out;
}

TEST(PartRows, CentresOnALineAreARowAndASquareIsNot) {
  const auto row = boxesAt({{0, 0, 0}, {4, 0.2f, 0}, {8, 0, 0}, {12, 0, 0}});
  const auto line = partRow(firstParts(4), row, 0.25f);
  ASSERT_TRUE(line.has_value());
  EXPECT_NEAR(line->spacing, 4.0f, 1e-4f);
  EXPECT_NEAR(line->last - line->first, 12.0f, 1e-4f);
  EXPECT_NEAR(std::abs(line->direction.x()), 1.0f, 1e-4f);
  // Burner caps in a square, two parts only, and a row one of whose parts stands off its line.
  EXPECT_FALSE(
      partRow(firstParts(4), boxesAt({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {4, 4, 0}}), 0.25f));
  EXPECT_FALSE(partRow(firstParts(2), boxesAt({{0, 0, 0}, {4, 0, 0}}), 0.25f));
  EXPECT_FALSE(partRow(firstParts(3), boxesAt({{0, 0, 0}, {4, 2, 0}, {8, 0, 0}}), 0.25f));
}

TEST(PartRows, ALargerPartOnTheLineBeyondTheEndContinuesTheRow) {
  // A row of three (spacing 4), then at x = 14 a part 1.25 times larger: on the line, 1.5
  // spacings beyond; another as large off the line, one twice as large, one too far, one between
  // two parts of the row (not beyond its end).
  const auto parts = boxesAt(
      {{0, 0, 0}, {4, 0, 0}, {8, 0, 0}, {14, 0, 0}, {14, 5, 0}, {-6, 0, 0}, {30, 0, 0}, {2, 0, 0}},
      {1, 1, 1, 1.25f, 1.25f, 2.0f, 1.25f, 1.25f});
  const std::vector<std::size_t> family = firstParts(3);
  const auto row = partRow(family, parts, 0.25f);
  ASSERT_TRUE(row.has_value());
  // Candidates as the repeated-parts pass gives them: the first part's scaled copies outside the
  // family.
  const auto scaledCopies = [&](float maxScale) {
    std::vector<std::size_t> out;
    for (std::size_t q : PartCopies(parts, kCopyTolerance, maxScale).of(0))
      if (q >= family.size()) out.push_back(q);
    return out;
  };
  const auto next = rowContinuations(*row, scaledCopies(1.5f), parts, 0.25f, 2.0f);
  ASSERT_EQ(next.size(), 1u);
  EXPECT_TRUE(parts[next[0]].centroid.isApprox(Eigen::Vector3f(14, 0, 0), 1e-4f));
  // Scaled copies only within maxScale: none at 1.2.
  EXPECT_TRUE(rowContinuations(*row, scaledCopies(1.2f), parts, 0.25f, 2.0f).empty());
}

}  // namespace
}  // namespace sagrid
