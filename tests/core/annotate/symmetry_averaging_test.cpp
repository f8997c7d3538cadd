#include "core/annotate/symmetry_averaging.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "core/model/affordance_model.h"
#include "support/untrained_models.h"

namespace sagrid {
namespace {

// A random sparse grid with channels (nx, ny, nz, a): a normal and one scalar.
FeatureGrid randomGrid(int resolution, unsigned seed) {
  FeatureGrid g;
  g.backend = "test";
  g.configHash = "test";
  g.resolution = resolution;
  g.channels = 4;
  g.descriptor = {0.1f, 0.2f};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1);
  for (int i = 0; i < resolution; ++i)
    for (int j = 0; j < resolution; ++j)
      for (int k = 0; k < resolution; ++k)
        if (u(rng) > 0.4f) {
          g.voxels.push_back({i, j, k});
          for (int c = 0; c < 4; ++c) g.values.push_back(u(rng));
        }
  return g;
}

const std::vector<std::array<int, 3>> kNormal = {{0, 1, 2}};

TEST(SymmetryAveraging, SymmetriesArePermutationsOfTheGrid) {
  const int r = 6;
  for (const auto& s : gridSymmetries()) {
    std::set<std::tuple<int, int, int>> seen;
    for (int i = 0; i < r; ++i)
      for (int j = 0; j < r; ++j)
        for (int k = 0; k < r; ++k) {
          const VoxelIndex v = applySymmetry({i, j, k}, s, r);
          ASSERT_TRUE(v.i >= 0 && v.i < r && v.j >= 0 && v.j < r && v.k == k);
          seen.insert({v.i, v.j, v.k});
        }
    EXPECT_EQ(seen.size(), static_cast<std::size_t>(r * r * r));
  }
  // Four quarter turns are the identity; a quarter turn takes +x to +y.
  VoxelIndex v{5, 2, 1};
  for (int t = 0; t < 4; ++t) v = applySymmetry(v, {1, false}, r);
  EXPECT_EQ(v, (VoxelIndex{5, 2, 1}));
  EXPECT_EQ(applySymmetry({5, 2, 1}, {1, false}, r), (VoxelIndex{3, 5, 1}));
}

TEST(SymmetryAveraging, NormalsTurnWithTheirVoxels) {
  FeatureGrid g;
  g.resolution = 4;
  g.channels = 4;
  g.voxels = {{3, 1, 0}};            // on the +x side
  g.values = {1.0f, 0.0f, 0.0f, 7};  // normal +x
  std::vector<std::size_t> order;
  const FeatureGrid turned = transformFeatureGrid(g, {1, false}, kNormal, &order);
  EXPECT_EQ(turned.voxels[0], (VoxelIndex{2, 3, 0}));  // now on the +y side
  EXPECT_FLOAT_EQ(turned.values[0], 0.0f);
  EXPECT_FLOAT_EQ(turned.values[1], 1.0f);  // normal +y
  EXPECT_FLOAT_EQ(turned.values[3], 7.0f);  // scalars unchanged
  const FeatureGrid flipped = transformFeatureGrid(g, {0, true}, kNormal);
  EXPECT_EQ(flipped.voxels[0], (VoxelIndex{0, 1, 0}));
  EXPECT_FLOAT_EQ(flipped.values[0], -1.0f);
}

TEST(SymmetryAveraging, TransformedVoxelsStaySortedAndCarryTheirFeatures) {
  const FeatureGrid g = randomGrid(6, 4);
  std::vector<std::size_t> order;
  const FeatureGrid t = transformFeatureGrid(g, {3, true}, kNormal, &order);
  ASSERT_EQ(t.voxels.size(), g.voxels.size());
  for (std::size_t n = 1; n < t.voxels.size(); ++n) EXPECT_TRUE(t.voxels[n - 1] < t.voxels[n]);
  for (std::size_t n = 0; n < t.voxels.size(); ++n) {
    EXPECT_EQ(t.voxels[n], applySymmetry(g.voxels[order[n]], {3, true}, 6));
    EXPECT_FLOAT_EQ(t.values[n * 4 + 3], g.values[order[n] * 4 + 3]);
  }
}

TEST(SymmetryAveraging, AveragedFieldIsEquivariantForAnyModel) {
  // Averaging over the whole group makes the field equivariant even for an untrained model: the
  // field of a turned object is the turned field.
  const FeatureGrid g = randomGrid(8, 11);
  const model::AffordanceModel model = test::untrainedModelFor("stove.heatsource", g, 5);
  const std::vector<float> field = symmetryAveragedDistances(model, g, kNormal);
  std::vector<std::size_t> order;
  const FeatureGrid turned = transformFeatureGrid(g, {1, true}, kNormal, &order);
  const std::vector<float> turnedField = symmetryAveragedDistances(model, turned, kNormal);
  ASSERT_EQ(field.size(), turnedField.size());
  for (std::size_t n = 0; n < turnedField.size(); ++n)
    EXPECT_NEAR(turnedField[n], field[order[n]], 1e-4f * (1 + field[order[n]]));
  // One copy is the plain prediction; the plain prediction is not equivariant by itself.
  EXPECT_EQ(symmetryAveragedDistances(model, g, kNormal, 1), model.predictDistances(g));
  const std::vector<float> plainTurned = model.predictDistances(turned);
  const std::vector<float> plain = model.predictDistances(g);
  double differs = 0;
  for (std::size_t n = 0; n < plain.size(); ++n)
    differs = std::max(differs, static_cast<double>(std::abs(plainTurned[n] - plain[order[n]])));
  EXPECT_GT(differs, 1e-3);
}

TEST(SymmetryAveraging, CopiesPredictedSideBySideEqualCopiesPredictedOneByOneBitForBit) {
  // The copies' passes run on parallel threads, each on one intra-op thread (issue 42): every
  // copy's field, and their sum in the copies' order, are those of one pass after another.
  const FeatureGrid g = randomGrid(10, 13);
  const model::AffordanceModel model = test::untrainedModelFor("stove.heatsource", g, 5);
  std::vector<FeatureGrid> copies;
  std::vector<std::vector<std::size_t>> orders(8);
  for (int i = 0; i < 8; ++i)
    copies.push_back(transformFeatureGrid(g, gridSymmetries()[i], kNormal, &orders[i]));
  std::vector<const FeatureGrid*> grids;
  for (const auto& c : copies) grids.push_back(&c);
  const std::vector<std::vector<float>> together = model.predictDistances(grids);
  ASSERT_EQ(together.size(), 8u);
  std::vector<float> sum(g.voxels.size(), 0.0f);
  for (int i = 0; i < 8; ++i) {
    const std::vector<float> alone = model.predictDistances(copies[i]);
    EXPECT_EQ(together[i], alone) << "copy " << i;
    for (std::size_t o = 0; o < alone.size(); ++o) sum[orders[i][o]] += alone[o];
  }
  for (float& d : sum) d /= 8.0f;
  EXPECT_EQ(symmetryAveragedDistances(model, g, kNormal), sum);
}

}  // namespace
}  // namespace sagrid
