// Frame time of the annotation GUI, headless (EGL; Mesa llvmpipe on a CPU-only machine): the full
// frame function (panels + mesh + field + markers) at 1280x800, with the distance field shown
// on all 64^3 voxels (the worst case) and on the occupied surface voxels of a real object.
// Each iteration draws one frame and waits for it (glFinish); the camera orbits a little each
// frame. Reports wall time per frame, fps, and process CPU ms per frame. Run:
//   build/tests/benchmarks/gui_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "ui/app/app.h"
#include "ui/document/distance_field.h"
#include "ui/gl/gl.h"

namespace {

namespace fs = std::filesystem;
using namespace sagrid::ui;

fs::path sceneDir() {
  const fs::path dir = fs::temp_directory_path() / "sagrid-gui-bench";
  fs::create_directories(dir);
  std::ofstream obj(dir / "mesh.obj");
  obj << "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\nv 0 0 0.8\n"
         "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nf 1 3 2\nf 1 4 3\n";
  std::ofstream(dir / "labels.json")
      << R"({"schema":"sagrid.labels/1","object":{"id":"pyramid","mesh":"mesh.obj","category":"stove","up":"z"},)"
      << R"("affordances":[{"type":"heatsource","position":[0,0,0.8],"status":"predicted"}]})";
  return dir;
}

double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

void frames(benchmark::State& state, bool fullGrid, bool showField = true) {
  ContextOptions options;
  options.width = 1280;
  options.height = 800;
  auto context = createGlContext(GlBackend::Egl, options);
  AppOptions appOptions;
  appOptions.autoPredict = false;
  App app(*context, appOptions);
  const fs::path dir =
      fullGrid ? sceneDir()
               : fs::path(SAGRID_SOURCE_DIR) / "../shared/data/real-dev/libero__flat_stove";
  if (!fs::exists(dir / "mesh.obj")) {
    state.SkipWithError("real-dev object not found");
    return;
  }
  // Read-only: the benchmark never edits, so nothing is written back.
  app.session().openObject(dir / "mesh.obj", dir / "labels.json");
  auto* doc = app.session().document();
  if (fullGrid) {
    const auto voxels = allVoxels(doc->gridResolution());
    std::vector<DistanceField> fields = {distanceFieldFromPoints(
        "heatsource", voxels, doc->gridResolution(), doc->normalization(), {doc->pointInView(0)})};
    doc->setPredictedFields(std::move(fields));
  }
  app.session().view().field.visible = showField;
  app.session().view().field.threshold = 1e9f;  // every voxel shown
  app.frame({});
  app.frame({});
  glFinish();
  const double cpuBefore = processCpuSeconds();
  for (auto _ : state) {
    app.session().camera().orbit(0.01f, 0.0f);  // a moving camera, as while orbiting
    app.frame({});
    glFinish();
  }
  // Process CPU time (all llvmpipe threads) per frame: on a shared machine the wall time above
  // depends on the load; this does not. On an idle machine wall ~ cpu / cores used.
  state.counters["cpu_ms_per_frame"] =
      1e3 * (processCpuSeconds() - cpuBefore) / double(state.iterations());
  state.counters["cubes"] = double(app.scene().field().instanceCount());
  state.counters["fps"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_GuiFrameFullGrid64(benchmark::State& state) { frames(state, true); }
void BM_GuiFrameSurfaceVoxelsStove(benchmark::State& state) { frames(state, false); }
void BM_GuiFrameStoveNoField(benchmark::State& state) { frames(state, false, false); }  // reference

BENCHMARK(BM_GuiFrameFullGrid64)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_GuiFrameSurfaceVoxelsStove)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_GuiFrameStoveNoField)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace
