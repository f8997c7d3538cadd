#include "core/physics/solid_voxels.h"

#include <algorithm>

#include "core/common/error.h"
#include "core/grid/voxelize.h"
#include "core/mesh/mesh.h"

namespace sagrid::physics {

namespace {

using Mask = std::vector<std::uint8_t>;

// Grows `mask` by `radius` voxels with a cube structuring element (three separable passes).
Mask dilate(const Mask& mask, int n, int radius) {
  Mask current = mask;
  const std::size_t strides[3] = {static_cast<std::size_t>(n) * n, static_cast<std::size_t>(n), 1};
  for (int axis = 0; axis < 3 && radius > 0; ++axis) {
    Mask next(current.size(), 0);
    const std::size_t s = strides[axis];
    for (std::size_t index = 0; index < current.size(); ++index) {
      if (!current[index]) continue;
      const int coordinate = static_cast<int>((index / s) % n);
      const int lo = std::max(0, coordinate - radius), hi = std::min(n - 1, coordinate + radius);
      const std::size_t base = index - static_cast<std::size_t>(coordinate) * s;
      for (int c = lo; c <= hi; ++c) next[base + static_cast<std::size_t>(c) * s] = 1;
    }
    current.swap(next);
  }
  return current;
}

// Voxels reachable from the grid's border through voxels not in `walls` (6-connected).
Mask floodFromBorder(const Mask& walls, int n) {
  Mask outside(walls.size(), 0);
  std::vector<std::size_t> stack;
  auto visit = [&](int i, int j, int k) {
    const std::size_t index = (static_cast<std::size_t>(i) * n + j) * n + k;
    if (walls[index] || outside[index]) return;
    outside[index] = 1;
    stack.push_back(index);
  };
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      visit(0, a, b), visit(n - 1, a, b), visit(a, 0, b);
      visit(a, n - 1, b), visit(a, b, 0), visit(a, b, n - 1);
    }
  while (!stack.empty()) {
    const std::size_t index = stack.back();
    stack.pop_back();
    const int i = static_cast<int>(index / (static_cast<std::size_t>(n) * n));
    const int j = static_cast<int>((index / n) % n), k = static_cast<int>(index % n);
    if (i > 0) visit(i - 1, j, k);
    if (i < n - 1) visit(i + 1, j, k);
    if (j > 0) visit(i, j - 1, k);
    if (j < n - 1) visit(i, j + 1, k);
    if (k > 0) visit(i, j, k - 1);
    if (k < n - 1) visit(i, j, k + 1);
  }
  return outside;
}

}  // namespace

SolidVoxels solidVoxels(const Mesh& mesh, int resolution, int closingVoxels,
                        const std::optional<Eigen::AlignedBox3f>& frame) {
  if (mesh.triangles.empty()) throw Error("the mesh has no triangles");
  if (resolution < 8 || closingVoxels < 0 || 2 * (closingVoxels + 2) >= resolution / 2)
    throw InvalidArgument("voxel resolution " + std::to_string(resolution) + " with " +
                          std::to_string(closingVoxels) + " closing voxels is out of range");
  Eigen::AlignedBox3f box = mesh.bounds();
  if (frame) box.extend(*frame);
  if (const auto problem = normalizationProblem(box)) throw Error("the mesh " + *problem);

  SolidVoxels result{Normalization::fromBounds(box), VoxelGrid(resolution), VoxelGrid(resolution)};
  // Leave a margin so that the outside wraps the mesh and the closing has room.
  // The box also spans a fraction of a voxel less than the inner grid and sits off the voxel
  // lattice by a non-dyadic shift: voxelize's exact triangle-box test decides faces that lie
  // exactly on a voxel boundary by float rounding, and with the box's faces on the boundaries
  // (an axis-aligned box normalized to whole voxels) whole faces could fall between two voxels.
  const int margin = closingVoxels + 2;
  result.normalization.scale *= static_cast<float>(resolution - 2 * margin - 0.5) / resolution;
  const float shift = 0.2371f / (resolution * result.normalization.scale);  // mesh units
  result.normalization.center -= Eigen::Vector3f::Constant(shift);

  Mesh normalized;  // positions and triangles only: voxelize needs nothing else
  normalized.triangles = mesh.triangles;
  normalized.positions.reserve(mesh.positions.size());
  for (const auto& p : mesh.positions) normalized.positions.push_back(result.normalization.toNormalized(p));
  result.surface = voxelize(normalized, resolution);

  const Mask& surface = result.surface.occupancy();
  const Mask outsideOpen = floodFromBorder(surface, resolution);
  Mask outside = outsideOpen;
  if (closingVoxels > 0) {
    outside = dilate(floodFromBorder(dilate(surface, resolution, closingVoxels), resolution),
                     resolution, closingVoxels);
    for (std::size_t index = 0; index < outside.size(); ++index)
      outside[index] = outside[index] && outsideOpen[index];
  }
  for (std::size_t index = 0; index < outside.size(); ++index) {
    if (outside[index]) continue;
    result.solid.setOccupied(result.solid.fromLinear(index));
    if (!surface[index]) ++result.enclosedCount;
    if (outsideOpen[index]) ++result.closedCount;
  }
  return result;
}

}  // namespace sagrid::physics
