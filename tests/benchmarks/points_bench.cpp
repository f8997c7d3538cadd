// Point extraction speed on a field of annotate's size: the occupied shell of a 64^3 box (about
// 23k voxels), distances to five burners plus noise. Side by side: the paper's argmin, the
// automatic count (basin depths of every minimum, threshold, suppression, sub-voxel refinement)
// and k-means with the true count.
// Run: build/tests/benchmarks/points_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <random>

#include "core/points/point_extraction.h"

namespace {

using sagrid::PredictedField;

PredictedField shellField() {
  PredictedField f;
  f.resolution = 64;
  const std::vector<Eigen::Vector3f> burners = {{-0.3f, -0.3f, 0.48f}, {0.3f, -0.3f, 0.48f},
                                                {-0.3f, 0.3f, 0.48f},  {0.3f, 0.3f, 0.48f},
                                                {0.0f, 0.0f, 0.48f}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> noise(-0.01f, 0.01f);
  for (int i = 1; i < 63; ++i)
    for (int j = 1; j < 63; ++j)
      for (int k = 1; k < 63; ++k) {
        if (i != 1 && i != 62 && j != 1 && j != 62 && k != 1 && k != 62) continue;
        const sagrid::VoxelIndex v{i, j, k};
        float d = 1e9f;
        for (const auto& b : burners) d = std::min(d, (sagrid::voxelCenter(v, 64) - b).norm());
        f.voxels.push_back(v);
        f.distances.push_back(std::max(0.0f, d + noise(rng)));
      }
  return f;
}

sagrid::ExtractionSettings cardLike() {
  sagrid::ExtractionSettings s;
  s.maxDistance = 0.04f;
  s.maxDistanceAboveBest = true;
  s.minPersistence = 0.01f;
  s.nmsRadius = 0.16f;
  s.refineVoxels = 2.0f;
  return s;
}

void BM_Argmin(benchmark::State& state) {
  const auto f = shellField();
  for (auto _ : state) benchmark::DoNotOptimize(sagrid::argminPoint(f, cardLike()));
  state.counters["voxels"] = static_cast<double>(f.voxels.size());
}
BENCHMARK(BM_Argmin)->Unit(benchmark::kMillisecond);

void BM_FieldMinima(benchmark::State& state) {
  const auto f = shellField();
  for (auto _ : state) benchmark::DoNotOptimize(sagrid::fieldMinima(f));
}
BENCHMARK(BM_FieldMinima)->Unit(benchmark::kMillisecond);

void BM_AutoCount(benchmark::State& state) {
  const auto f = shellField();
  std::size_t points = 0;
  for (auto _ : state) points = sagrid::autoCountPoints(f, cardLike()).size();
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_AutoCount)->Unit(benchmark::kMillisecond);

void BM_KMeansTrueCount(benchmark::State& state) {
  const auto f = shellField();
  for (auto _ : state) benchmark::DoNotOptimize(sagrid::kMeansPoints(f, 5, cardLike()));
}
BENCHMARK(BM_KMeansTrueCount)->Unit(benchmark::kMillisecond);

}  // namespace
