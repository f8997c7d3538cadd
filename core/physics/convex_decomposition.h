// Convex decomposition of a triangle mesh into a bounded number of convex collision parts, for
// the simulator exports (`--collision decompose`), and the single hull of `--collision hull`.
//
// Method (ours, in the spirit of V-HACD and CoACD): the mesh is voxelized (core/grid/voxelize),
// filled from outside (see solid_voxels.h) and its surface clipped into the voxels; parts are
// sets of solid voxels whose hull is taken over the exact surface pieces inside them. The part
// with the largest concavity is cut by the axis-aligned plane that best lowers the concavity of
// its two sides, split into connected pieces, until every part is within the tolerance or the
// part budget is spent; then pairs are merged back while the budget is exceeded. Concavity of a
// part is the largest distance from its hull's surface to the mesh's solid (the outside distance
// field of the filled voxels), so cavities (sink basins, oven interiors) are never spanned by one
// hull while the budget allows.
#pragma once

#include <Eigen/Geometry>
#include <atomic>
#include <functional>
#include <string>
#include <optional>
#include <vector>

#include "core/physics/convex_part.h"

namespace sagrid {

struct Mesh;

namespace physics {

// fraction in [0, 1] and the stage running ("voxelizing", "cutting", "merging", "hulls").
using DecompositionProgress = std::function<void(float fraction, const std::string& stage)>;

struct DecompositionOptions {
  int maxParts = 32;
  // Voxels along the mesh's largest extent. Time and memory grow with its cube.
  int resolution = 64;
  // Stop cutting a part when its concavity is below this fraction of the largest extent.
  float concavityTolerance = 0.01f;
  // Vertices per hull (MuJoCo and V-HACD use 64-ish; 0 = unlimited).
  int maxVerticesPerPart = 64;
  // Holes in the surface narrower than about 2 * this many voxels are closed before filling.
  int holeClosingVoxels = 1;
  // The box the voxel grid spans, when not the mesh's own bounds (solid_voxels.h): a body with
  // its moving parts cut away is cut on the whole object's grid, so the cut does not move.
  std::optional<Eigen::AlignedBox3f> frame;
  DecompositionProgress progress;         // optional
  const std::atomic<bool>* cancel = nullptr;  // optional; throws Cancelled when set
};

struct Decomposition {
  std::vector<ConvexPart> parts;  // in the mesh's frame and units
  // The largest part concavity left when it stopped, in mesh units (the cutting criterion's own
  // estimate on the voxel grid; the benchmark measures concavity on the surface exactly).
  float concavity = 0.0f;
  // Things a user should know (open surface, thin or flat mesh thickened, budget reached).
  std::vector<std::string> warnings;
};

// Throws InvalidArgument for options out of range and Error for a mesh with no triangles or no
// extent. A flat mesh (a single plane) gives one thin box-like part and a warning.
Decomposition decomposeConvex(const Mesh& mesh, const DecompositionOptions& options = {});

// The convex hull of the whole mesh (`--collision hull`), thickened when flat. Throws Error for a
// mesh with no triangles or no extent.
ConvexPart convexHullPart(const Mesh& mesh, int maxVertices = 0);

}  // namespace physics
}  // namespace sagrid
