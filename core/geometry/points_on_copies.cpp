#include "core/geometry/points_on_copies.h"

#include "core/geometry/connected_parts.h"
#include "core/geometry/crease_patches.h"
#include "core/geometry/material_parts.h"
#include "core/mesh/mesh.h"

namespace sagrid {

std::vector<Eigen::Vector3f> placesOnCopies(const Eigen::Vector3f& point, std::size_t on,
                                            const std::vector<ConnectedPart>& parts,
                                            const PartCopies& copies) {
  std::vector<Eigen::Vector3f> out;
  for (std::size_t c : copies.of(on)) out.push_back(point + parts[c].centroid - parts[on].centroid);
  return out;
}

namespace {

// Where `point` lands on the copies of the small part of `parts` it lies on; empty where none.
std::vector<Eigen::Vector3f> placesAmong(const std::vector<ConnectedPart>& parts,
                                         const Eigen::Vector3f& point, float largest) {
  const auto on = partAt(point, parts, kCopyTouchShare * largest, kSmallPartDiagonal * largest);
  if (!on) return {};
  return placesOnCopies(point, *on, parts, PartCopies(parts, kCopyTolerance));
}

}  // namespace

std::vector<Eigen::Vector3f> pointsOnCopies(const Mesh& mesh, const Eigen::Vector3f& point) {
  const std::vector<ConnectedPart> parts = connectedAndMaterialParts(mesh);
  Eigen::AlignedBox3f all;
  for (const auto& part : parts) all.extend(part.box);
  if (all.isEmpty() || !point.allFinite()) return {};
  const float largest = all.sizes().maxCoeff();
  auto places = placesAmong(parts, point, largest);
  if (places.empty()) places = placesAmong(creasePatches(mesh), point, largest);
  return places;
}

}  // namespace sagrid
