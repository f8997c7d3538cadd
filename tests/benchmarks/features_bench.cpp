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

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kRealDev = {"libero__basin_faucet", "libero__faucet_knob",
                                           "libero__flat_stove"};

fs::path realDevMesh(int i) {
  return fs::path(SAGRID_SOURCE_DIR) / ".." / "shared" / "data" / "real-dev" / kRealDev[i] /
         "mesh.obj";
}

fs::path benchDir() {
  const fs::path dir = fs::temp_directory_path() / "sagrid-features-bench";
  fs::create_directories(dir);
  return dir;
}

// Splits every triangle into n x n (n chosen for >= 100k triangles) and writes an OBJ with the
// surface albedo as vertex colours, so the big mesh looks like the original.
fs::path denseCopy(int i) {
  static std::map<int, fs::path> done;
  if (done.count(i)) return done[i];
  const sagrid::Mesh mesh = sagrid::importMesh(realDevMesh(i));
  const int n = static_cast<int>(std::ceil(std::sqrt(100000.0 / mesh.triangleCount())));
  const fs::path path = benchDir() / (kRealDev[i] + "_dense.obj");
  std::ofstream out(path);
  std::size_t vertices = 0, triangles = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3f a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                          c = mesh.positions[tri[2]];
    auto index = [&](int r, int s) {
      return vertices + 1 + static_cast<std::size_t>(r * (r + 1) / 2 + s);
    };
    for (int r = 0; r <= n; ++r) {
      for (int s = 0; s <= r; ++s) {
        const float u = static_cast<float>(r - s) / n, v = static_cast<float>(s) / n;
        const Eigen::Vector3f p = a + u * (b - a) + v * (c - a);
        const Eigen::Vector3f col = mesh.albedo(static_cast<int>(t), u, v);
        out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << col.x() << ' ' << col.y()
            << ' ' << col.z() << '\n';
      }
    }
    for (int r = 0; r < n; ++r) {
      for (int s = 0; s <= r; ++s) {
        out << "f " << index(r, s) << ' ' << index(r + 1, s) << ' ' << index(r + 1, s + 1) << '\n';
        ++triangles;
        if (s < r) {
          out << "f " << index(r, s) << ' ' << index(r + 1, s + 1) << ' ' << index(r, s + 1)
              << '\n';
          ++triangles;
        }
      }
    }
    vertices += static_cast<std::size_t>((n + 1) * (n + 2) / 2);
  }
  std::fprintf(stderr, "%s: %zu triangles\n", path.c_str(), triangles);
  return done[i] = path;
}

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
