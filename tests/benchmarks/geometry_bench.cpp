// Geometry core speed: import (OBJ), normalize, voxelize at 64^3, and projection of 10,000 points
// onto the surface, on generated bumpy spheres of about 10k / 100k / 1M triangles.
// Run: build/tests/benchmarks/geometry_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>

#include "core/geometry/surface_scene.h"
#include "core/grid/normalization.h"
#include "core/grid/voxelize.h"
#include "core/mesh/mesh.h"
#include "core/mesh/mesh_import.h"

namespace {
namespace fs = std::filesystem;
using sagrid::Mesh;

// A sphere with bumps (so triangles are not all alike), about `triangles` triangles.
Mesh bumpySphere(int triangles) {
  const int rings = std::max(4, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
  const int segments = 2 * rings;
  Mesh mesh;
  for (int i = 0; i <= rings; ++i) {
    const double theta = M_PI * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * M_PI * j / segments;
      const double r = 0.3 * (1.0 + 0.08 * std::sin(7 * theta) * std::cos(5 * phi));
      mesh.positions.emplace_back(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                                  r * std::cos(theta));
    }
  }
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      const int a = i * segments + j, b = i * segments + (j + 1) % segments;
      mesh.triangles.emplace_back(a, a + segments, b + segments);
      mesh.triangles.emplace_back(a, b + segments, b);
    }
  }
  mesh.computeVertexNormals();
  return mesh;
}

const Mesh& cachedMesh(int triangles) {
  static std::map<int, Mesh> cache;
  auto it = cache.find(triangles);
  if (it == cache.end()) it = cache.emplace(triangles, bumpySphere(triangles)).first;
  return it->second;
}

// The mesh written once as OBJ to a temporary file.
fs::path cachedObj(int triangles) {
  const fs::path path = fs::temp_directory_path() / ("sagrid-bench-" + std::to_string(triangles) + ".obj");
  if (!fs::exists(path)) {
    const Mesh& mesh = cachedMesh(triangles);
    std::ofstream out(path);
    char line[128];
    for (const auto& p : mesh.positions) {
      std::snprintf(line, sizeof(line), "v %.7g %.7g %.7g\n", p.x(), p.y(), p.z());
      out << line;
    }
    for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  return path;
}

// What projection is for: predicted points a few voxels off the surface. Vertices of the mesh
// moved by up to +-2 voxels of a 64^3 grid over the object (about 0.03 here) in each axis.
std::vector<Eigen::Vector3f> nearSurfacePoints(const Mesh& mesh, std::size_t count) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<std::size_t> vertex(0, mesh.positions.size() - 1);
  std::uniform_real_distribution<float> offset(-0.03f, 0.03f);
  std::vector<Eigen::Vector3f> points(count);
  for (auto& p : points) p = mesh.positions[vertex(rng)] + Eigen::Vector3f(offset(rng), offset(rng), offset(rng));
  return points;
}

// A harder case: uniform in the bounding cube, including points deep inside the sphere that are
// almost equally far from every triangle.
std::vector<Eigen::Vector3f> uniformPoints(std::size_t count) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-0.45f, 0.45f);
  std::vector<Eigen::Vector3f> points(count);
  for (auto& p : points) p = Eigen::Vector3f(u(rng), u(rng), u(rng));
  return points;
}

void setCounters(benchmark::State& state, int triangles) {
  state.counters["triangles"] = static_cast<double>(cachedMesh(triangles).triangleCount());
}

void BM_Import(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const fs::path obj = cachedObj(n);
  for (auto _ : state) benchmark::DoNotOptimize(sagrid::importMesh(obj));
  setCounters(state, n);
}

void BM_Normalize(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Mesh& mesh = cachedMesh(n);
  for (auto _ : state) {
    const auto normalization = sagrid::Normalization::fromMesh(mesh);
    benchmark::DoNotOptimize(sagrid::normalizedCopy(mesh, normalization));
  }
  setCounters(state, n);
}

void BM_Voxelize64(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Mesh& mesh = cachedMesh(n);
  const Mesh normalized = sagrid::normalizedCopy(mesh, sagrid::Normalization::fromMesh(mesh));
  std::size_t occupied = 0;
  for (auto _ : state) occupied = sagrid::voxelize(normalized, 64).occupiedCount();
  setCounters(state, n);
  state.counters["occupied"] = static_cast<double>(occupied);
}

void BM_SceneBuild(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Mesh& mesh = cachedMesh(n);
  for (auto _ : state) benchmark::DoNotOptimize(sagrid::SurfaceScene(mesh));
  setCounters(state, n);
}

// 10,000 closest-point projections of near-surface points on all hardware threads
// (SurfaceScene::closestPoints).
void BM_Project10k(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const sagrid::SurfaceScene scene(cachedMesh(n));
  const auto queries = nearSurfacePoints(cachedMesh(n), 10000);
  for (auto _ : state) benchmark::DoNotOptimize(scene.closestPoints(queries));
  setCounters(state, n);
}

// The same on one thread.
void BM_Project10kOneThread(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const sagrid::SurfaceScene scene(cachedMesh(n));
  const auto queries = nearSurfacePoints(cachedMesh(n), 10000);
  for (auto _ : state) {
    for (const auto& q : queries) benchmark::DoNotOptimize(scene.closestPoint(q));
  }
  setCounters(state, n);
}

// Uniform points in the cube, all threads.
void BM_Project10kUniform(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const sagrid::SurfaceScene scene(cachedMesh(n));
  const auto queries = uniformPoints(10000);
  for (auto _ : state) benchmark::DoNotOptimize(scene.closestPoints(queries));
  setCounters(state, n);
}

#define SAGRID_SIZES Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_Import)->SAGRID_SIZES->Iterations(3);
BENCHMARK(BM_Normalize)->SAGRID_SIZES;
BENCHMARK(BM_Voxelize64)->SAGRID_SIZES;
BENCHMARK(BM_SceneBuild)->SAGRID_SIZES->Iterations(3);
BENCHMARK(BM_Project10k)->SAGRID_SIZES;
BENCHMARK(BM_Project10kOneThread)->SAGRID_SIZES;
BENCHMARK(BM_Project10kUniform)->SAGRID_SIZES;

}  // namespace
