#include "core/physics/decomposition_quality.h"

#include <algorithm>

#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"
#include "core/physics/signed_volume.h"
#include "core/physics/solid_voxels.h"
#include "core/physics/surface_sampling.h"

namespace sagrid::physics {

namespace {

// A hull as planes n.x <= d (n unit) with its box, for fast point tests.
struct HalfSpaces {
  std::vector<Eigen::Vector4f> planes;
  Eigen::AlignedBox3f box;

  explicit HalfSpaces(const ConvexPart& part) {
    for (const auto& v : part.vertices) box.extend(v);
    for (const auto& t : part.triangles) {
      const Eigen::Vector3f a = part.vertices[t[0]];
      Eigen::Vector3f n = (part.vertices[t[1]] - a).cross(part.vertices[t[2]] - a);
      if (n.norm() == 0) continue;
      n.normalize();
      planes.emplace_back(n.x(), n.y(), n.z(), n.dot(a));
    }
  }
  // Inside, with `margin` > 0 demanding that depth and < 0 allowing that much outside.
  bool contains(const Eigen::Vector3f& p, float margin = 0) const {
    if (box.exteriorDistance(p) > std::max(0.0f, -margin)) return false;
    for (const auto& h : planes)
      if (h.head<3>().dot(p) - h.w() > -margin) return false;
    return true;
  }
};

}  // namespace

DecompositionQuality measureDecomposition(const Mesh& mesh, const std::vector<ConvexPart>& parts,
                                          double spacing, int resolution) {
  DecompositionQuality quality;
  const double diagonal = mesh.bounds().diagonal().norm();
  const SurfaceScene scene(mesh);
  std::vector<HalfSpaces> hulls;
  for (const auto& part : parts) hulls.emplace_back(part);
  const float step = static_cast<float>(spacing * diagonal);
  const float margin = 1e-6f * static_cast<float>(diagonal);
  std::vector<Eigen::Vector3f> samples;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    quality.hullVolume += parts[p].volume();
    sampleTriangles(parts[p].vertices, parts[p].triangles, step, [&](const Eigen::Vector3f& q) {
      for (std::size_t other = 0; other < hulls.size(); ++other)
        if (other != p && hulls[other].contains(q, margin)) return;  // inside the union
      samples.push_back(q);
    });
  }
  // Only points outside the mesh count: a hull surface point inside the solid (two parts that
  // do not quite meet deep inside a thick wall) is missing coverage, which the IoU measures.
  // Outside: in a voxel outside the filled solid, or in a surface voxel and in front of the
  // nearest triangle.
  const SolidVoxels solid = solidVoxels(mesh, resolution, 2);
  const double outward = signedVolume(mesh) < 0 ? -1.0 : 1.0;
  const auto nearest = scene.closestPoints(samples);
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const VoxelIndex v = voxelContaining(solid.normalization.toNormalized(samples[s]), resolution);
    const bool outside = !solid.solid.occupied(v) ||
                         (solid.surface.occupied(v) &&
                          outward * (samples[s] - nearest[s].position).dot(nearest[s].normal) > 0);
    if (outside) quality.concavity = std::max(quality.concavity, static_cast<double>(nearest[s].distance));
  }
  quality.relativeConcavity = diagonal > 0 ? quality.concavity / diagonal : 0;

  const std::vector<VoxelIndex> voxels = solid.solid.occupiedVoxels();
  // Surface voxels count when their centre is behind the nearest triangle (outward winding
  // assumed, as every exporter writes it); enclosed voxels always.
  std::vector<Eigen::Vector3f> centres;
  std::vector<std::size_t> surfaceAt;
  for (std::size_t v = 0; v < voxels.size(); ++v)
    if (solid.surface.occupied(voxels[v])) {
      centres.push_back(solid.normalization.toMesh(voxelCenter(voxels[v], resolution)));
      surfaceAt.push_back(v);
    }
  std::vector<char> inMesh(voxels.size(), 1);
  if (solid.enclosedCount > 0) {
    const auto nearest = scene.closestPoints(centres);
    for (std::size_t s = 0; s < centres.size(); ++s)
      inMesh[surfaceAt[s]] = outward * (centres[s] - nearest[s].position).dot(nearest[s].normal) <= 0;
  }
  // Voxels whose centre is in some hull: each hull marks the voxels of its own box.
  const int n = resolution;
  std::vector<char> inHull(solid.solid.voxelCount(), 0);
  for (const HalfSpaces& hull : hulls) {
    const VoxelIndex lo = voxelContaining(solid.normalization.toNormalized(hull.box.min()), n);
    const VoxelIndex hi = voxelContaining(solid.normalization.toNormalized(hull.box.max()), n);
    for (int i = lo.i; i <= hi.i; ++i)
      for (int j = lo.j; j <= hi.j; ++j)
        for (int k = lo.k; k <= hi.k; ++k) {
          const VoxelIndex v{i, j, k};
          char& mark = inHull[solid.solid.linearIndex(v)];
          if (!mark && hull.contains(solid.normalization.toMesh(voxelCenter(v, n)))) mark = 1;
        }
  }
  std::vector<char> inMeshGrid(solid.solid.voxelCount(), 0);
  for (std::size_t v = 0; v < voxels.size(); ++v) inMeshGrid[solid.solid.linearIndex(voxels[v])] = inMesh[v];
  std::size_t both = 0, meshOnly = 0, hullOnly = 0;
  for (std::size_t v = 0; v < inHull.size(); ++v) {
    both += inHull[v] && inMeshGrid[v];
    meshOnly += !inHull[v] && inMeshGrid[v];
    hullOnly += inHull[v] && !inMeshGrid[v];
  }
  const std::size_t unionCount = both + meshOnly + hullOnly;
  quality.volumeIoU = unionCount > 0 ? static_cast<double>(both) / unionCount : 0;
  return quality;
}

}  // namespace sagrid::physics
