// Normalization into the unit cube as TRELLIS does it: scale by 1 / (largest bounding-box
// extent) and move the box centre to the origin, so the object fits [-0.5, 0.5]^3. The forward
// and inverse maps are kept so every point shown or written is in the mesh's own frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "core/mesh/bounds_check.h"

namespace sagrid {

struct Mesh;

struct Normalization {
  Eigen::Vector3f center = Eigen::Vector3f::Zero();  // bounding-box centre, mesh frame
  float scale = 1.0f;                                // 1 / largest extent

  static Normalization fromBounds(const Eigen::AlignedBox3f& box);  // throws Error, see below
  static Normalization fromMesh(const Mesh& mesh);

  Eigen::Vector3f toNormalized(const Eigen::Vector3f& meshPoint) const {
    return (meshPoint - center) * scale;
  }
  Eigen::Vector3f toMesh(const Eigen::Vector3f& normalizedPoint) const {
    return normalizedPoint / scale + center;
  }
  // Distances: normalized length -> mesh-frame length.
  float lengthToMesh(float normalizedLength) const { return normalizedLength / scale; }
};

// Returns a copy of `mesh` with positions mapped into the normalized frame.
Mesh normalizedCopy(const Mesh& mesh, const Normalization& normalization);

}  // namespace sagrid
