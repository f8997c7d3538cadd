// `sagrid extract MESH|DIR --out DIR`: per-voxel features and object descriptors of meshes,
// written as .npz (for the model and for Python tools), with an on-disk cache, a progress bar
// for folders, and optional TRELLIS-layout view renders and feature preview pictures.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/command_registry.h"
#include "app/commands/up_axis_option.h"
#include "app/progress_bar.h"
#include "core/common/atomic_file.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/features/feature_npz.h"
#include "core/features/feature_pipeline.h"
#include "core/features/feature_preview.h"
#include "core/grid/normalization.h"
#include "core/mesh/mesh_files.h"
#include "core/mesh/mesh_import.h"
#include "core/render/trellis_views.h"
#include "core/render/view_export.h"

namespace {

struct ExtractOptions {
  std::string input, out, backend = "embedded", cache, up, dinov2Model, trellisLatents;
  std::string aggregation, exportViews, preview, previewChannel = "albedo_r";
  int resolution = sagrid::kDefaultGridResolution;
  int views = sagrid::kTrellisViewCount;
  int renderSize = 0;
};

sagrid::FeatureOptions toFeatureOptions(const ExtractOptions& o) {
  sagrid::FeatureOptions f;
  f.backend = o.backend;
  f.resolution = o.resolution;
  f.cacheDir = o.cache;
  if (!o.up.empty()) f.up = sagrid::parseUpAxis(o.up);
  f.dinov2Model = o.dinov2Model;
  f.trellisLatents = o.trellisLatents;
  f.views = o.views;
  if (o.renderSize > 0) f.renderSize = o.renderSize;
  if (o.aggregation == "mean") f.aggregation = sagrid::Aggregation::Mean;
  if (o.aggregation == "occlusion") f.aggregation = sagrid::Aggregation::OcclusionAware;
  return f;
}

struct FramedFile {
  sagrid::FeatureOptions options;     // with the up axis the features are read in
  std::optional<float> upConfidence;  // set when the axis was detected
  std::optional<sagrid::Mesh> mesh;   // imported to detect the axis: features and extras reuse it
};

// Without --up the up axis is detected from the geometry as `annotate` and `filter` do, so the
// features of a y-up OBJ are not those of the object lying on its side.
FramedFile inFileFrame(const sagrid::FeatureOptions& options, const std::filesystem::path& path) {
  FramedFile framed{options, std::nullopt, std::nullopt};
  if (options.up) return framed;
  framed.mesh = sagrid::importMesh(path, sagrid::ImportOptions(std::nullopt, /*detect=*/true));
  framed.options.up = framed.mesh->fileUp;
  if (framed.mesh->fileUpDetected) framed.upConfidence = framed.mesh->fileUpConfidence;
  return framed;
}

// Renders and previews need the mesh itself; imported here when asked for and not imported yet.
void writeExtras(const ExtractOptions& o, const FramedFile& framed, const sagrid::MeshFile& file,
                 const sagrid::FeatureGrid& grid) {
  namespace fs = std::filesystem;
  if (o.exportViews.empty() && o.preview.empty()) return;
  const sagrid::FeatureOptions& f = framed.options;
  const sagrid::Mesh mesh =
      framed.mesh ? *framed.mesh : sagrid::importMesh(file.path, sagrid::ImportOptions(f.up));
  if (!o.exportViews.empty()) {
    const sagrid::Mesh normalized = sagrid::normalizedCopy(mesh, grid.normalization);
    const auto cameras = sagrid::trellisViews(f.views, sagrid::seedFromKey(mesh.sha256));
    sagrid::exportViews(normalized, cameras, f.renderSize.value_or(512),
                        fs::path(o.exportViews) / file.id,
                        /*withDepth=*/true);
  }
  if (!o.preview.empty()) {
    const auto names = sagrid::featureChannelNames(f);
    const auto it = std::find(names.begin(), names.end(), o.previewChannel);
    if (it == names.end()) {
      throw sagrid::InvalidArgument("--preview-channel: no channel '" + o.previewChannel +
                                    "' in backend " + o.backend);
    }
    fs::create_directories(o.preview);
    sagrid::writeFileAtomic(
        fs::path(o.preview) / (file.id + "_" + o.previewChannel + ".png"),
        sagrid::renderFeaturePreviewPng(mesh, grid, static_cast<int>(it - names.begin()),
                                        sagrid::previewCamera(), 512));
  }
}

void setupExtract(CLI::App& root) {
  auto* cmd = root.add_subcommand("extract",
                                  "Extract per-voxel features and the object descriptor of a mesh, "
                                  "or of every mesh under a folder, "
                                  "into OUT/<id>.npz (keys coords int32 Nx3, feats float32 NxC, "
                                  "descriptor, normalization_center, "
                                  "normalization_scale, metadata = UTF-8 JSON bytes). Backends: "
                                  "embedded (default; CPU, no download), "
                                  "dinov2 (TorchScript dinov2_vitl14_reg, TRELLIS protocol), "
                                  "trellis (TRELLIS SLAT .npz latents).");
  auto o = std::make_shared<ExtractOptions>();
  cmd->add_option("input", o->input, "Mesh file or folder of meshes (searched recursively)")
      ->required();
  cmd->add_option("--out", o->out, "Output folder for <id>.npz")->required();
  cmd->add_option("--backend", o->backend, "embedded, dinov2 or trellis")
      ->check(CLI::IsMember({"embedded", "embedded-texture", "dinov2", "trellis"}));
  cmd->add_option(
      "--cache", o->cache,
      "Feature cache folder (keyed by mesh sha256 + feature config; damaged entries are rebuilt)");
  sagrid::app::addUpAxisOption(*cmd, o->up, sagrid::app::kDetectedUpDefault);
  cmd->add_option("--dinov2-model", o->dinov2Model,
                  "TorchScript DINOv2 file (packaging/python/export_dinov2.py) for dinov2, and for "
                  "trellis descriptors");
  cmd->add_option("--trellis-latents", o->trellisLatents,
                  "TRELLIS latent .npz, or folder of <mesh sha256>.npz");
  cmd->add_option("--resolution", o->resolution, "Voxel grid resolution")
      ->check(CLI::Range(4, 256));
  cmd->add_option("--views", o->views, "Number of rendered views (TRELLIS: 150)")
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--render-size", o->renderSize,
                  "View size in pixels (default: embedded 96, dinov2 518)")
      ->check(CLI::Range(8, 4096));
  cmd->add_option("--aggregation", o->aggregation,
                  "mean (TRELLIS: every view) or occlusion (only views that see the voxel); "
                  "default per backend")
      ->check(CLI::IsMember({"mean", "occlusion"}));
  cmd->add_option("--export-views", o->exportViews,
                  "Also write the views as TRELLIS renders: DIR/<id>/NNN.png + transforms.json");
  cmd->add_option("--preview", o->preview,
                  "Also write DIR/<id>_<channel>.png: a view coloured by one channel");
  cmd->add_option("--preview-channel", o->previewChannel,
                  "Channel name for --preview (default albedo_r)");
  cmd->callback([o] {
    namespace fs = std::filesystem;
    const sagrid::FeatureOptions options = toFeatureOptions(*o);
    (void)sagrid::featureChannels(options);  // rejects a bad backend before any work
    const std::vector<sagrid::MeshFile> files = sagrid::findMeshFiles(o->input);
    if (files.empty()) throw sagrid::FileError(o->input, "no mesh files found");
    std::error_code ec;
    fs::create_directories(o->out, ec);
    if (ec) throw sagrid::FileError(o->out, "cannot create output folder: " + ec.message());

    std::unique_ptr<sagrid::app::ProgressBar> bar;
    if (files.size() > 1) bar = std::make_unique<sagrid::app::ProgressBar>("extract", files.size());
    std::vector<double> seconds;
    std::vector<std::string> failures;
    int cachedCount = 0;
    for (std::size_t i = 0; i < files.size(); ++i) {
      const auto& file = files[i];
      if (bar) bar->update(i, file.id);
      const auto start = std::chrono::steady_clock::now();
      try {
        bool cached = false;
        const FramedFile framed = inFileFrame(options, file.path);
        // Without a cache the mesh imported for the axis gives the features; with one, a cached
        // entry spares the features (the import for the axis is needed either way).
        const sagrid::FeatureGrid grid =
            framed.mesh && options.cacheDir.empty()
                ? sagrid::computeFeatures(*framed.mesh, framed.options)
                : sagrid::extractFeatures(file.path, framed.options, &cached);
        nlohmann::json meta = {{"id", file.id},
                               {"mesh", fs::absolute(file.path).string()},
                               {"up", sagrid::toString(*framed.options.up)}};
        if (framed.upConfidence) meta["up_confidence"] = *framed.upConfidence;
        sagrid::writeFeatureNpz(fs::path(o->out) / (file.id + ".npz"), grid, meta);
        writeExtras(*o, framed, file, grid);
        cachedCount += cached;
        seconds.push_back(sagrid::secondsSince(start));
      } catch (const sagrid::InvalidArgument&) {
        throw;  // the same for every file: stop at once
      } catch (const sagrid::ModelError&) {
        throw;
      } catch (const sagrid::Error& e) {
        if (files.size() == 1) throw;
        failures.push_back(e.what());
      }
    }
    if (bar) {
      bar->update(files.size());
      bar->finish();
    }
    std::sort(seconds.begin(), seconds.end());
    const double median = seconds.empty() ? 0.0 : seconds[seconds.size() / 2];
    std::printf(
        "extract: %zu of %zu meshes -> %s (%d from cache), %s backend, median %.3f s per mesh\n",
        seconds.size(), files.size(), o->out.c_str(), cachedCount, o->backend.c_str(), median);
    if (!failures.empty()) {
      for (const auto& f : failures) std::fprintf(stderr, "extract: failed: %s\n", f.c_str());
      throw sagrid::Error(std::to_string(failures.size()) + " of " + std::to_string(files.size()) +
                          " meshes failed (listed above)");
    }
  });
}

SAGRID_REGISTER_COMMAND("extract", setupExtract);

}  // namespace
