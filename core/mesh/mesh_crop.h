// The part of a mesh inside a box: triangles inside are kept as they are, triangles crossing the
// box are clipped to it (vertex normals, UVs and colours interpolated), materials and textures
// kept, so the crop renders like the original. Positions keep the mesh's own (z-up) frame, so
// points found on the crop are points of the original mesh. Large triangles matter: a counter
// top of two triangles still surrounds a cropped tap.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace sagrid {

// The region rule of the coarse-to-fine second pass (core/annotate/coarse_to_fine.h), which its
// training crops (core/training/crop_dataset.h) follow too: the box around the points grown by
// kCropMargin x the object's largest extent on every side, no crop wider than kCropMaxShare x that
// extent, none with fewer than kCropMinTriangles triangles.
inline constexpr float kCropMargin = 0.15f;
inline constexpr float kCropMaxShare = 0.6f;
inline constexpr int kCropMinTriangles = 12;

// The box around `points` (mesh frame) grown by `margin` x the largest extent of `bounds` and
// clipped to `bounds`; nullopt, with the reason in `why`, when it is empty or wider than
// `maxShare` x that extent.
std::optional<Eigen::AlignedBox3f> regionAround(const std::vector<Eigen::Vector3f>& points,
                                                const Eigen::AlignedBox3f& bounds, float margin,
                                                float maxShare, std::string* why = nullptr);

// An empty mesh (no triangles) when nothing of the mesh lies in `box`.
Mesh cropMesh(const Mesh& mesh, const Eigen::AlignedBox3f& box);

}  // namespace sagrid
