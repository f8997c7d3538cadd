// What one click of the GUI's part brush costs in core: the brushed triangles (a 3 cm ball around
// the click, over the welded surface) and the part described again (its motion, axis and pivot),
// on the ~100k-triangle copies of the real-dev objects, clicking at each object's first toggle
// point. "WeldEachClick" welds the whole mesh on every click (the brush before the welded surface
// was kept per mesh); "Welded" reuses one PartEditSurface, as the GUI now does.
// Run: build/tests/benchmarks/part_edit_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <map>

#include "core/controls/control_part.h"
#include "core/controls/control_part_edit.h"
#include "core/geometry/surface_scene.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"
#include "real_dev_meshes.h"

namespace {

struct Click {
  sagrid::Mesh mesh;
  int triangle = -1;
  Eigen::Vector3f at = Eigen::Vector3f::Zero();
};

// The dense copy of real-dev object i and the surface point nearest its first toggle point (its
// first point where it has none).
const Click& clickOn(int i) {
  static std::map<int, Click> cache;
  auto it = cache.find(i);
  if (it != cache.end()) return it->second;
  Click click;
  click.mesh = sagrid::importMesh(sagrid::bench::denseCopy(i));
  const auto labels =
      sagrid::readLabels(sagrid::bench::realDevMesh(i).parent_path() / "labels.json");
  Eigen::Vector3f point = labels.affordances.empty() ? Eigen::Vector3f(click.mesh.bounds().center())
                                                     : labels.affordances.front().position;
  for (const auto& a : labels.affordances)
    if (a.type == "togglebutton") {
      point = a.position;
      break;
    }
  const sagrid::ClosestPoint nearest = sagrid::SurfaceScene(click.mesh).closestPoint(
      sagrid::fileToZUp(point, click.mesh.fileUp));
  click.triangle = nearest.triangle;
  click.at = nearest.position;
  return cache.emplace(i, std::move(click)).first->second;
}

constexpr float kRadius = 0.03f;  // real-dev files are in metres

void BM_BrushClickWeldEachClick(benchmark::State& state) {
  const Click& click = clickOn(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const auto part = sagrid::brushedPart(click.mesh, {}, click.triangle, click.at, kRadius, true);
    benchmark::DoNotOptimize(sagrid::describeControlPart(click.mesh, part, sagrid::PartOrigin::Marked));
  }
  state.counters["triangles"] = static_cast<double>(click.mesh.triangles.size());
}

void BM_BrushClickWelded(benchmark::State& state) {
  const Click& click = clickOn(static_cast<int>(state.range(0)));
  const sagrid::PartEditSurface surface(click.mesh);
  for (auto _ : state) {
    const auto part = sagrid::brushedPart(surface, {}, click.triangle, click.at, kRadius, true);
    benchmark::DoNotOptimize(sagrid::describeControlPart(click.mesh, part, sagrid::PartOrigin::Marked));
  }
  state.counters["triangles"] = static_cast<double>(click.mesh.triangles.size());
}

BENCHMARK(BM_BrushClickWeldEachClick)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BrushClickWelded)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
