#include "core/physics/mass_properties.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "core/common/error.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"
#include "core/physics/signed_volume.h"
#include "core/physics/solid_voxels.h"

namespace sagrid::physics {

namespace {

// Share of each surface voxel inside the solid: the nearest triangle's plane cuts the voxel
// cube, the share below it taken linearly from the signed distance of the voxel centre
// (exact for planes along a grid axis). Voxel-sized in the normalized frame.
std::vector<double> insideShares(const Mesh& mesh, const SolidVoxels& solid,
                                 const std::vector<VoxelIndex>& surfaceVoxels) {
  const int n = solid.surface.resolution();
  const double h = solid.voxelSize();
  std::vector<Eigen::Vector3f> centres;
  centres.reserve(surfaceVoxels.size());
  for (const auto& v : surfaceVoxels) centres.push_back(solid.normalization.toMesh(voxelCenter(v, n)));
  const SurfaceScene scene(mesh);
  const std::vector<ClosestPoint> nearest = scene.closestPoints(centres);
  const double outward = signedVolume(mesh) < 0 ? -1.0 : 1.0;
  std::vector<double> shares(surfaceVoxels.size());
  for (std::size_t s = 0; s < surfaceVoxels.size(); ++s) {
    const Eigen::Vector3d normal = outward * nearest[s].normal.cast<double>();
    const double signedDistance = (centres[s] - nearest[s].position).cast<double>().dot(normal);
    const double halfWidth = 0.5 * h * std::max(1.0, normal.cwiseAbs().sum());
    shares[s] = std::clamp(0.5 - 0.5 * signedDistance / halfWidth, 0.0, 1.0);
  }
  return shares;
}

}  // namespace

MassProperties estimateMassProperties(const Mesh& mesh, const MassOptions& options) {
  if (!(options.metersPerUnit > 0) || !std::isfinite(options.metersPerUnit))
    throw InvalidArgument("metres per unit must be a positive number");
  if (options.density < 0 || !std::isfinite(options.density))
    throw InvalidArgument("density must be a positive number of kg/m^3");
  if (options.resolution < 16 || options.resolution > 512)
    throw InvalidArgument("mass resolution " + std::to_string(options.resolution) +
                          " is out of range (16 to 512)");
  const SolidVoxels solid = solidVoxels(mesh, options.resolution, options.holeClosingVoxels);

  MassProperties result;
  result.density = options.density > 0 ? options.density : densityFor(options.category).kilogramsPerCubicMetre;
  result.surfaceOpen = solid.closedCount > 0 || solid.enclosedCount == 0;
  const bool shellOnly = solid.enclosedCount == 0;
  if (shellOnly)
    result.warnings.push_back("the mesh encloses no volume (open or flat); its one-voxel shell is weighed");
  else if (solid.closedCount > 0)
    result.warnings.push_back("the surface has holes; they were closed before filling");

  const int n = solid.solid.resolution();
  std::vector<VoxelIndex> surfaceVoxels, enclosedVoxels;
  for (const auto& v : solid.solid.occupiedVoxels())
    (solid.surface.occupied(v) ? surfaceVoxels : enclosedVoxels).push_back(v);
  const std::vector<double> shares =
      shellOnly ? std::vector<double>(surfaceVoxels.size(), 1.0) : insideShares(mesh, solid, surfaceVoxels);

  // Moments in metres, accumulated about the grid centre for precision.
  const double h = solid.voxelSize() * options.metersPerUnit;
  const Eigen::Vector3d origin = solid.normalization.toMesh(Eigen::Vector3f::Zero()).cast<double>() * options.metersPerUnit;
  double weight = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // sum w r r^T
  auto add = [&](const VoxelIndex& v, double w) {
    const Eigen::Vector3d r =
        solid.normalization.toMesh(voxelCenter(v, n)).cast<double>() * options.metersPerUnit - origin;
    weight += w;
    first += w * r;
    second += w * r * r.transpose();
  };
  for (const auto& v : enclosedVoxels) add(v, 1.0);
  for (std::size_t s = 0; s < surfaceVoxels.size(); ++s) add(surfaceVoxels[s], shares[s]);
  if (!(weight > 0)) throw Error("the mesh encloses no volume to weigh");

  const double cell = h * h * h;
  result.volume = weight * cell;
  result.mass = result.volume * result.density;
  const Eigen::Vector3d centre = first / weight;
  result.centerOfMass = origin + centre;
  // Second moment about the centre plus each voxel's own cube inertia (side h: m h^2 / 6).
  const Eigen::Matrix3d spread = second / weight - centre * centre.transpose();
  result.inertia = result.mass * (spread.trace() * Eigen::Matrix3d::Identity() - spread) +
                   Eigen::Matrix3d::Identity() * (result.mass * h * h / 6.0);

  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(result.inertia);
  Eigen::Matrix3d axes = principal.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  result.principalMoments = principal.eigenvalues();
  result.principalAxes = Eigen::Quaterniond(axes).normalized();
  return result;
}

MassProperties withMass(const MassProperties& properties, double mass) {
  if (!(mass > 0) || !std::isfinite(mass)) throw InvalidArgument("mass must be a positive number of kg");
  MassProperties result = properties;
  const double factor = properties.mass > 0 ? mass / properties.mass : 0.0;
  result.mass = mass;
  result.density = properties.volume > 0 ? mass / properties.volume : properties.density;
  result.inertia *= factor;
  result.principalMoments *= factor;
  return result;
}

}  // namespace sagrid::physics
