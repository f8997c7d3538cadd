// Feature extraction entry points: mesh -> FeatureGrid (per-voxel features + object descriptor),
// with pluggable backends behind one option struct and an on-disk cache keyed by the mesh file's
// sha256 and a hash of the feature configuration.
//
// Backends:
//   "embedded" (default) — no download, CPU, ~1 s: multi-view albedo/normal/visibility aggregated
//                into voxels plus geometric channels; kEmbeddedChannels per voxel and a
//                kEmbeddedDescriptorSize-d object descriptor (see embedded_features.h).
//   "embedded-texture" — the embedded channels plus sub-voxel texture detail (texture_detail.h):
//                kEmbeddedChannels + 2 per voxel, the same descriptor.
//   "dinov2"   — TRELLIS protocol with a user-supplied TorchScript dinov2_vitl14_reg
//                (options.dinov2Model): 150 views, 518^2, pre-norm patch tokens 37x37x1024,
//                bilinear sampling, mean over views; 1024 channels, 1024-d descriptor (mean patch
//                feature).
//   "trellis"  — TRELLIS SLAT latents from TRELLIS's own toolkit (options.trellisLatents: a
//                <sha256>.npz file or a folder of them; coords uint8 N x 3, feats float32 N x 8);
//                8 channels; descriptor from dinov2 when options.dinov2Model is set, else the
//                embedded descriptor.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/features/feature_grid.h"
#include "core/grid/voxel_grid.h"
#include "core/mesh/mesh.h"

namespace sagrid {

constexpr int kEmbeddedChannels = 16;
constexpr int kEmbeddedDescriptorSize = 64;
constexpr int kDinov2Channels = 1024;
constexpr int kTrellisLatentChannels = 8;

// How per-view samples are combined into a voxel.
enum class Aggregation {
  Mean,            // TRELLIS: every view counts, occluded or not
  OcclusionAware,  // only views whose depth buffer shows the voxel (depth test, ~1 voxel slack)
};

struct FeatureOptions {
  std::string backend = "embedded";  // "embedded" | "embedded-texture" | "dinov2" | "trellis"
  int resolution = kDefaultGridResolution;
  std::filesystem::path cacheDir;        // empty = no cache
  std::optional<UpAxis> up;              // override the file's up axis on import
  std::filesystem::path dinov2Model;     // TorchScript dinov2_vitl14_reg (dinov2, trellis)
  std::filesystem::path trellisLatents;  // <sha256>.npz or a folder of them (trellis)

  // Rendering/aggregation; unset = the backend's default (embedded: 150 views at 96^2,
  // occlusion-aware; dinov2: 150 views at 518^2, plain mean as TRELLIS).
  int views = 150;
  std::optional<int> renderSize;
  std::optional<Aggregation> aggregation;
};

// Per-voxel channel count and descriptor size the options produce (for model cards and layers).
// Throws InvalidArgument for an unknown backend.
int featureChannels(const FeatureOptions& options);
int descriptorSize(const FeatureOptions& options);
// Names of the per-voxel channels (e.g. "albedo_r"), featureChannels() long.
std::vector<std::string> featureChannelNames(const FeatureOptions& options);
// Hash of everything in the options that changes the features (not cacheDir/up handling of the
// file, which is covered by the mesh); stored in FeatureGrid::configHash.
std::string featureConfigHash(const FeatureOptions& options);

// Features of an already imported mesh (z-up, mesh frame). No cache. The "trellis" backend needs
// mesh.sha256 to find its latent file.
FeatureGrid computeFeatures(const Mesh& mesh, const FeatureOptions& options);

// Imports the mesh file and computes its features, reading/writing the cache in
// options.cacheDir when set. Corrupt or stale cache entries are rebuilt, never trusted.
// `fromCache` (optional) tells whether the result came from the cache.
FeatureGrid extractFeatures(const std::filesystem::path& meshFile, const FeatureOptions& options,
                            bool* fromCache = nullptr);

}  // namespace sagrid
