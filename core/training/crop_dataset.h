// Training data for the coarse-to-fine second pass (core/annotate/coarse_to_fine.h): for every
// labelled object of a dataset and every affordance type on it, the region the second pass would
// cut out around that type's points — the box around them, shifted at random as a first pass
// that missed by a few centimetres would shift it, grown by the same margin, clipped to the
// object — written as an object of its own with the points inside it. A model trained beside
// these sees parts at the scale the second pass shows them (a tap on a 1 m counter spans 4x as
// many voxels in its crop), which it never does on whole objects.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "core/mesh/mesh_crop.h"

namespace sagrid {

struct CropDatasetOptions {
  float margin = kCropMargin;          // share of the object's largest extent (the second pass')
  float maxCropShare = kCropMaxShare;  // no crop wider than this share (no second pass there)
  float jitter = 0.05f;       // the box moves by up to this share of the extent on each axis
  int minTriangles = kCropMinTriangles;  // fewer in the crop: none written
  std::uint64_t seed = 1;
};

struct CropDatasetSummary {
  int objects = 0;  // labelled objects read
  int crops = 0;    // crops written
  int skipped =
      0;  // (object, type) pairs with no crop: too wide, too few triangles, no point inside
};

// Writes outDir/<object id>.<type>/mesh.obj (z-up, the object's units) + labels.json (category and
// meters_per_unit kept; every point of any type inside the crop) and outDir/manifest.jsonl.
// Throws FileError for an unreadable dataset or an outDir that cannot be written; objects whose
// mesh or labels cannot be read are skipped with a warning.
CropDatasetSummary writeCropDataset(const std::filesystem::path& dataDir,
                                    const std::filesystem::path& outDir,
                                    const CropDatasetOptions& options = {},
                                    const std::function<void(int done, int total)>& progress = {});

}  // namespace sagrid
