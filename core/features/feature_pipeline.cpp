#include "core/features/feature_pipeline.h"

#include <chrono>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/common/sha256.h"
#include "core/features/dinov2_encoder.h"
#include "core/features/dinov2_features.h"
#include "core/features/embedded_features.h"
#include "core/features/feature_cache.h"
#include "core/features/texture_detail.h"
#include "core/features/trellis_latents.h"
#include "core/geometry/surface_scene.h"
#include "core/grid/normalization.h"
#include "core/grid/voxelize.h"
#include "core/mesh/mesh_import.h"
#include "core/render/trellis_views.h"

namespace sagrid {

namespace {
// Bump when the embedded features change meaning, so caches of older versions are rebuilt.
constexpr int kEmbeddedVersion = 1;
constexpr int kDefaultEmbeddedRenderSize = 96;

enum class Backend { Embedded, EmbeddedTexture, Dinov2, Trellis };

Backend parseBackend(const std::string& name) {
  if (name == "embedded") return Backend::Embedded;
  if (name == "embedded-texture") return Backend::EmbeddedTexture;
  if (name == "dinov2") return Backend::Dinov2;
  if (name == "trellis") return Backend::Trellis;
  throw InvalidArgument("unknown feature backend '" + name +
                        "' (choose embedded, embedded-texture, dinov2 or trellis)");
}

// Whether the views go through DINOv2 (dinov2, and trellis with a model for its descriptor) or
// the embedded encoder (embedded, and trellis without a model).
bool usesDinov2(const FeatureOptions& o, Backend b) {
  return b == Backend::Dinov2 || (b == Backend::Trellis && !o.dinov2Model.empty());
}

int renderSizeOf(const FeatureOptions& o, Backend b) {
  if (o.renderSize) return *o.renderSize;
  return usesDinov2(o, b) ? kDinov2InputSize : kDefaultEmbeddedRenderSize;
}

Aggregation aggregationOf(const FeatureOptions& o, Backend b) {
  if (o.aggregation) return *o.aggregation;
  return usesDinov2(o, b) ? Aggregation::Mean : Aggregation::OcclusionAware;
}

void validate(const FeatureOptions& o) {
  const Backend b = parseBackend(o.backend);
  if (o.resolution < 4 || o.resolution > 256) {
    throw InvalidArgument("feature grid resolution must be in [4, 256], got " +
                          std::to_string(o.resolution));
  }
  if (o.views < 1 || o.views > 10000) {
    throw InvalidArgument("number of views must be in [1, 10000], got " + std::to_string(o.views));
  }
  const int size = renderSizeOf(o, b);
  if (size < 8 || size > 4096) {
    throw InvalidArgument("render size must be in [8, 4096], got " + std::to_string(size));
  }
  if (b == Backend::Dinov2 && o.dinov2Model.empty()) {
    throw InvalidArgument(
        "the dinov2 backend needs a TorchScript model (--dinov2-model FILE; "
        "export one with packaging/python/export_dinov2.py)");
  }
  if (b == Backend::Trellis && o.trellisLatents.empty()) {
    throw InvalidArgument("the trellis backend needs TRELLIS latents (--trellis-latents FILE|DIR)");
  }
  if (b == Backend::Trellis && o.resolution != kDefaultGridResolution) {
    throw InvalidArgument("TRELLIS latents live on a 64^3 grid; resolution " +
                          std::to_string(o.resolution) +
                          " is not possible with the trellis backend");
  }
}

// Identifies a model file cheaply but safely enough for a cache key: size + hash of its head
// and tail (hashing a 1.2 GB ViT-L on every run would cost seconds).
std::string modelFingerprint(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "missing:" + file.string();
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  constexpr std::streamoff kChunk = 1 << 20;
  std::string head(static_cast<std::size_t>(std::min(size, kChunk)), '\0');
  in.seekg(0);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  std::string tail(static_cast<std::size_t>(std::min(size, kChunk)), '\0');
  in.seekg(size - static_cast<std::streamoff>(tail.size()));
  in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  return std::to_string(size) + ":" + sha256Hex(head + tail);
}

// Geometry-derived seed key for meshes without a file hash (generated in memory).
std::string geometryKey(const Mesh& mesh) {
  std::string bytes;
  bytes.reserve(mesh.positions.size() * 12 + mesh.triangles.size() * 12);
  for (const auto& p : mesh.positions) bytes.append(reinterpret_cast<const char*>(p.data()), 12);
  for (const auto& t : mesh.triangles) bytes.append(reinterpret_cast<const char*>(t.data()), 12);
  return sha256Hex(bytes);
}

// Per-voxel rows of `a` (aChannels wide) followed by those of `b`.
std::vector<float> appendChannels(const std::vector<float>& a, int aChannels,
                                  const std::vector<float>& b, int bChannels) {
  const std::size_t rows = a.size() / static_cast<std::size_t>(aChannels);
  std::vector<float> out;
  out.reserve(a.size() + b.size());
  for (std::size_t r = 0; r < rows; ++r) {
    out.insert(out.end(), a.begin() + r * aChannels, a.begin() + (r + 1) * aChannels);
    out.insert(out.end(), b.begin() + r * bChannels, b.begin() + (r + 1) * bChannels);
  }
  return out;
}
}  // namespace

int featureChannels(const FeatureOptions& options) {
  switch (parseBackend(options.backend)) {
    case Backend::Embedded:
      return kEmbeddedChannels;
    case Backend::EmbeddedTexture:
      return kEmbeddedChannels + kTextureDetailChannels;
    case Backend::Dinov2:
      return kDinov2Channels;
    case Backend::Trellis:
      return kTrellisLatentChannels;
  }
  return 0;
}

int descriptorSize(const FeatureOptions& options) {
  switch (parseBackend(options.backend)) {
    case Backend::Embedded:
    case Backend::EmbeddedTexture:
      return kEmbeddedDescriptorSize;
    case Backend::Dinov2:
      return kDinov2Channels;
    case Backend::Trellis:
      return options.dinov2Model.empty() ? kEmbeddedDescriptorSize : kDinov2Channels;
  }
  return 0;
}

std::vector<std::string> featureChannelNames(const FeatureOptions& options) {
  const Backend b = parseBackend(options.backend);
  if (b == Backend::Embedded) return embedded::channelNames();
  if (b == Backend::EmbeddedTexture) {
    std::vector<std::string> names = embedded::channelNames();
    for (const auto& name : textureDetailChannelNames()) names.push_back(name);
    return names;
  }
  std::vector<std::string> names;
  const std::string prefix = b == Backend::Dinov2 ? "dinov2_" : "slat_";
  for (int c = 0; c < featureChannels(options); ++c) names.push_back(prefix + std::to_string(c));
  return names;
}

std::string featureConfigHash(const FeatureOptions& options) {
  const Backend b = parseBackend(options.backend);
  nlohmann::json config{{"backend", options.backend}, {"resolution", options.resolution}};
  config["views"] = options.views;
  config["render_size"] = renderSizeOf(options, b);
  config["aggregation"] = aggregationOf(options, b) == Aggregation::Mean ? "mean" : "occlusion";
  if (usesDinov2(options, b)) {
    config["dinov2_model"] = modelFingerprint(options.dinov2Model);
  } else {
    config["embedded_version"] = kEmbeddedVersion;
  }
  if (b == Backend::Trellis) {
    config["trellis_latents"] =
        std::filesystem::absolute(options.trellisLatents).lexically_normal().string();
  }
  return sha256Hex(config.dump()).substr(0, 16);
}

FeatureGrid computeFeatures(const Mesh& mesh, const FeatureOptions& options) {
  validate(options);
  const Backend backend = parseBackend(options.backend);
  const auto start = std::chrono::steady_clock::now();
  FeatureGrid out;
  out.backend = options.backend;
  out.configHash = featureConfigHash(options);
  out.resolution = options.resolution;
  out.channels = featureChannels(options);
  out.normalization = Normalization::fromMesh(mesh);
  const Mesh normalized = normalizedCopy(mesh, out.normalization);
  const VoxelGrid grid = voxelize(normalized, options.resolution);
  const double voxelizeSeconds = secondsSince(start);
  const SurfaceScene scene(normalized);
  const double sceneSeconds = secondsSince(start) - voxelizeSeconds;
  const std::uint64_t seed = seedFromKey(mesh.sha256.empty() ? geometryKey(mesh) : mesh.sha256);
  const int renderSize = renderSizeOf(options, backend);
  const Aggregation aggregation = aggregationOf(options, backend);

  switch (backend) {
    case Backend::Embedded:
    case Backend::EmbeddedTexture: {
      embedded::Settings settings;
      settings.views = options.views;
      settings.renderSize = renderSize;
      settings.aggregation = aggregation;
      embedded::Result r = embedded::compute(normalized, scene, grid, seed, settings);
      out.voxels = grid.occupiedVoxels();
      out.values = backend == Backend::Embedded
                       ? std::move(r.values)
                       : appendChannels(r.values, kEmbeddedChannels,
                                        textureDetail(normalized, grid), kTextureDetailChannels);
      out.descriptor = std::move(r.descriptor);
      break;
    }
    case Backend::Dinov2: {
      Dinov2Encoder encoder(options.dinov2Model, renderSize, kDinov2Channels);
      EncodedFeatures f =
          encodeViewsIntoVoxels(normalized, scene, grid, seed, options.views, encoder, aggregation);
      out.voxels = grid.occupiedVoxels();
      out.values = std::move(f.values);
      out.descriptor = std::move(f.descriptor);
      break;
    }
    case Backend::Trellis: {
      if (mesh.sha256.empty()) {
        throw InvalidArgument(
            "the trellis backend finds latents by the mesh file's sha256; this "
            "mesh has none (not imported from a file)");
      }
      TrellisLatents latents = readTrellisLatents(
          trellisLatentFile(options.trellisLatents, mesh.sha256), options.resolution);
      if (latents.channels != kTrellisLatentChannels) {
        throw FileError(trellisLatentFile(options.trellisLatents, mesh.sha256),
                        "feats has " + std::to_string(latents.channels) +
                            " channels; TRELLIS SLAT latents have 8");
      }
      out.voxels = std::move(latents.voxels);
      out.values = std::move(latents.feats);
      if (options.dinov2Model.empty()) {
        embedded::Settings settings;
        settings.views = options.views;
        settings.renderSize = renderSize;
        settings.aggregation = aggregation;
        out.descriptor = embedded::compute(normalized, scene, grid, seed, settings).descriptor;
      } else {
        Dinov2Encoder encoder(options.dinov2Model, renderSize, kDinov2Channels);
        out.descriptor = encodeViewsIntoVoxels(normalized, scene, grid, seed, options.views,
                                               encoder, aggregation, /*aggregateVoxels=*/false)
                             .descriptor;
      }
      break;
    }
  }
  const double total = secondsSince(start);
  logger()->info(
      "features ({}): {} voxels x {} channels in {:.3f} s (normalize+voxelize {:.3f}, "
      "BVH {:.3f}, views+features {:.3f})",
      options.backend, out.voxels.size(), out.channels, total, voxelizeSeconds, sceneSeconds,
      total - voxelizeSeconds - sceneSeconds);
  return out;
}

FeatureGrid extractFeatures(const std::filesystem::path& meshFile, const FeatureOptions& options,
                            bool* fromCache) {
  validate(options);
  if (fromCache) *fromCache = false;
  const std::string variant = options.up ? std::string("up") + toString(*options.up) : "";
  std::optional<FeatureCache> cache;
  std::string sha, hash;
  if (!options.cacheDir.empty()) {
    cache.emplace(options.cacheDir);
    sha = sha256Hex(readFileBytes(meshFile));
    hash = featureConfigHash(options);
    if (auto cached = cache->load(sha, hash, variant)) {
      if (fromCache) *fromCache = true;
      return std::move(*cached);
    }
  }
  const Mesh mesh = importMesh(meshFile, ImportOptions(options.up));
  FeatureGrid grid = computeFeatures(mesh, options);
  if (cache) cache->store(sha, hash, grid, variant);
  return grid;
}

}  // namespace sagrid
