// Feature extraction speed: the CPU renderer (rays/s) and the embedded backend end to end (mesh
// file -> cached features), on the real-dev objects and on ~100k-triangle versions of them
// (each triangle split into n x n, colours baked into vertex colours, written as OBJ).
//   build-x/tests/benchmarks/features_bench --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "core/common/thread_count.h"
#include "core/features/feature_pipeline.h"
#include "core/geometry/surface_scene.h"
#include "core/grid/normalization.h"
#include "core/mesh/mesh_import.h"
#include "core/render/multiview_renderer.h"
#include "core/render/trellis_views.h"
#include "real_dev_meshes.h"

namespace {

namespace fs = std::filesystem;
using sagrid::bench::benchDir;
using sagrid::bench::denseCopy;
using sagrid::bench::kRealDev;
using sagrid::bench::realDevMesh;

void renderViews(benchmark::State& state, const fs::path& file) {
  const sagrid::Mesh mesh = sagrid::importMesh(file);
  const sagrid::Mesh normalized =
      sagrid::normalizedCopy(mesh, sagrid::Normalization::fromMesh(mesh));
  const sagrid::SurfaceScene scene(normalized);
  const sagrid::MultiViewRenderer renderer(normalized, scene);
  const auto cameras = sagrid::trellisViews(sagrid::kTrellisViewCount, 1);
  const int size = static_cast<int>(state.range(0));
  for (auto _ : state) {
    std::size_t covered = 0;
    renderer.renderEach(
        cameras, size, sagrid::defaultThreadCount(),
        [&](int, int, const sagrid::RenderedView& v) { covered += v.mask[v.pixelCount() / 2]; });
    benchmark::DoNotOptimize(covered);
  }
  state.counters["rays_per_s"] =
      benchmark::Counter(static_cast<double>(cameras.size()) * size * size,
                         benchmark::Counter::kIsIterationInvariantRate);
  state.counters["triangles"] = static_cast<double>(mesh.triangleCount());
}

void BM_RenderViews_Dense(benchmark::State& state) { renderViews(state, denseCopy(2)); }
BENCHMARK(BM_RenderViews_Dense)->Arg(96)->Arg(518)->Unit(benchmark::kMillisecond)->UseRealTime();

// The stages of a cold extraction, separately: import (assimp + hashing) and in-memory features.
void BM_ImportMesh_Dense(benchmark::State& state) {
  const fs::path file = denseCopy(2);
  for (auto _ : state) benchmark::DoNotOptimize(sagrid::importMesh(file).positions.data());
}
BENCHMARK(BM_ImportMesh_Dense)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ComputeEmbedded_Dense(benchmark::State& state) {
  const sagrid::Mesh mesh = sagrid::importMesh(denseCopy(2));
  sagrid::FeatureOptions options;
  options.renderSize = static_cast<int>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(sagrid::computeFeatures(mesh, options).values.data());
}
BENCHMARK(BM_ComputeEmbedded_Dense)
    ->Arg(64)
    ->Arg(96)
    ->Arg(128)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Mesh file -> features in a fresh cache (import, voxelize, render, aggregate, write the entry).
void extractCold(benchmark::State& state, const fs::path& file) {
  sagrid::FeatureOptions options;
  options.cacheDir = benchDir() / "cache";
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(options.cacheDir);
    state.ResumeTiming();
    benchmark::DoNotOptimize(sagrid::extractFeatures(file, options).values.data());
  }
}

void BM_ExtractEmbedded_Dense(benchmark::State& state) {
  extractCold(state, denseCopy(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_ExtractEmbedded_Dense)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ExtractEmbedded_RealDev(benchmark::State& state) {
  extractCold(state, realDevMesh(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_ExtractEmbedded_RealDev)
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A cache hit: hash the file, read and verify the entry.
void BM_ExtractEmbedded_CacheHit(benchmark::State& state) {
  sagrid::FeatureOptions options;
  options.cacheDir = benchDir() / "cache-hit";
  const fs::path file = denseCopy(2);
  sagrid::extractFeatures(file, options);
  for (auto _ : state)
    benchmark::DoNotOptimize(sagrid::extractFeatures(file, options).values.data());
}
BENCHMARK(BM_ExtractEmbedded_CacheHit)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
