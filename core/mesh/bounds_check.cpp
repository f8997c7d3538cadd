#include "core/mesh/bounds_check.h"

#include <cstdio>

namespace sagrid {

namespace {
// Float keeps 24 bits; demanding 1e-3 relative size leaves about 130 float steps per voxel of a
// 64^3 grid, so voxelization and projection stay meaningful.
constexpr float kMinRelativeExtent = 1e-3f;
}  // namespace

std::optional<std::string> normalizationProblem(const Eigen::AlignedBox3f& box) {
  if (box.isEmpty()) return std::string("has no vertices");
  const Eigen::Vector3f extent = box.max() - box.min();
  if (!box.min().allFinite() || !box.max().allFinite() || !extent.allFinite()) {
    return std::string("has coordinates that are not finite or too large for float arithmetic");
  }
  const float largest = extent.maxCoeff();
  if (!(largest > 0.0f)) return std::string("has no extent (all vertices coincide)");
  const float farthest = box.min().cwiseAbs().cwiseMax(box.max().cwiseAbs()).maxCoeff();
  if (largest < kMinRelativeExtent * farthest) {
    char text[200];
    std::snprintf(text, sizeof(text),
                  "is too small (size %.3g) for its distance from the origin (%.3g): float "
                  "coordinates lose the detail; re-centre the mesh",
                  static_cast<double>(largest), static_cast<double>(farthest));
    return std::string(text);
  }
  return std::nullopt;
}

}  // namespace sagrid
