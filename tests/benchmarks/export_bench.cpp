// Simulator export time with moving controls (default) and with sites only (--no-controls), side
// by side on the same objects: the real-dev objects with their labels, MJCF and URDF, the default
// collision (convex decomposition). Skips where ../shared/data/real-dev is absent.
// Run: build/tests/benchmarks/export_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <filesystem>

#include "core/export/mjcf_export.h"
#include "core/export/omnigibson_export.h"
#include "core/labels/labels.h"
#include "real_dev_meshes.h"

namespace {

namespace fs = std::filesystem;

// Args: real-dev object, format (0 MJCF, 1 URDF), controls (1 moving parts, 0 sites only).
void BM_Export(benchmark::State& state) {
  const int object = static_cast<int>(state.range(0));
  const fs::path mesh = sagrid::bench::realDevMesh(object);
  const fs::path labelsPath = mesh.parent_path() / "labels.json";
  if (!fs::exists(labelsPath)) {
    state.SkipWithError("no ../shared/data/real-dev");
    return;
  }
  const sagrid::ObjectLabels labels = sagrid::readLabels(labelsPath);
  sagrid::ExportOptions options;
  options.articulatedControls = state.range(2) == 1;
  const fs::path out = sagrid::bench::benchDir() / "export";
  for (auto _ : state) {
    const auto result = state.range(1) == 0
                            ? sagrid::exportMjcf(labels, mesh, out, options, labelsPath)
                            : sagrid::exportOmniGibson(labels, mesh, out, options, labelsPath);
    benchmark::DoNotOptimize(result.massKg);
  }
  state.SetLabel(sagrid::bench::kRealDev[static_cast<std::size_t>(object)] +
                 (state.range(1) == 0 ? " mjcf" : " urdf") +
                 (state.range(2) == 1 ? " controls" : " sites-only"));
}
BENCHMARK(BM_Export)
    ->ArgsProduct({{0, 1, 2}, {0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
