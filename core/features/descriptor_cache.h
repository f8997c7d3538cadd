// Object descriptors alone, for filtering large collections (`sagrid filter`): a descriptor is
// what retrieval and the category classifier read (64 floats with the embedded backend), a small
// file beside the full feature entries in the cache folder, so a filter pass over a cached
// collection reads ~1 KB per mesh instead of a whole per-voxel grid and never voxelizes or
// renders. Keyed like the feature cache: mesh file sha256, feature-config hash, up override.
#pragma once

#include <array>
#include <filesystem>
#include <vector>

#include "core/features/feature_pipeline.h"
#include "core/geometry/part_statistics.h"
#include "core/grid/top_relief.h"

namespace sagrid {

enum class DescriptorSource {
  DescriptorCache,  // the small descriptor entry
  FeatureCache,     // a full feature entry (written by annotate/extract with the same cache)
  Computed,         // imported and computed; the descriptor entry is written for next time
};

// What the category decision reads of an object: its descriptor, the relief of its top
// (core/grid/top_relief.h, from the voxels the descriptor entry does not keep) and the statistics
// of its mesh's parts (core/geometry/part_statistics.h).
struct ObjectDescriptor {
  std::vector<float> descriptor;
  std::array<float, kTopReliefSize> topRelief{};
  std::array<float, kPartStatisticsSize> partStatistics{};
  bool hasPartStatistics = false;  // zero, not computed, when false
};

// The object descriptor of a mesh file with `options`' feature configuration, in the frame of
// options.up or, unset, of the up axis detected from the geometry (as `annotate`). With a cache
// folder (options.cacheDir) it reads the descriptor entry, else a full feature entry, else
// computes the features and stores the descriptor entry (not the grid: a collection of a
// million meshes would need terabytes). Unusable entries are ignored and rewritten, and so are
// entries written before they kept the top relief when `needTopRelief` (else their relief is
// left zero: a classifier that does not read it has no use for it) and entries without the part
// statistics when `needPartStatistics` (the mesh is then read for its parts; they are stored
// whenever the mesh was read).
ObjectDescriptor extractObjectDescriptor(const std::filesystem::path& meshFile,
                                         const FeatureOptions& options,
                                         DescriptorSource* source = nullptr,
                                         bool needTopRelief = true, bool needPartStatistics = true);
// Its descriptor alone.
std::vector<float> extractDescriptor(const std::filesystem::path& meshFile,
                                     const FeatureOptions& options,
                                     DescriptorSource* source = nullptr);

}  // namespace sagrid
