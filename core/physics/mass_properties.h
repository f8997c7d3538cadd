// Mass, centre of mass and inertia of an object for the simulator exports (MJCF <inertial>, URDF
// <inertial>): the solid volume from a voxel fill of the mesh (holes closed, filled from outside;
// see solid_voxels.h) times a per-category bulk density. Results are in SI units (kg, m, kg m^2)
// in the mesh's own z-up frame scaled to metres (mesh coordinates * metersPerUnit).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sagrid {

struct Mesh;

namespace physics {

struct DensityEntry {
  std::string_view category;  // SAGrid category ("stove", "sink", ...), "default" for the rest
  double kilogramsPerCubicMetre;
  std::string_view source;    // where the figure comes from
};

// The table, "default" last. Densities are bulk densities of the filled outer shape (a stove is
// a steel box full of air), not of the material.
const std::vector<DensityEntry>& densityTable();
// The entry for `category` (case-insensitive), or the "default" entry.
const DensityEntry& densityFor(std::string_view category);

struct MassOptions {
  double metersPerUnit = 1.0;
  std::string category;  // picks the density when density is 0
  double density = 0.0;  // kg/m^3; 0: from densityFor(category)
  int resolution = 128;  // voxels along the largest extent
  int holeClosingVoxels = 2;  // holes up to about 4 voxels across are closed
};

struct MassProperties {
  double volume = 0.0;                  // m^3
  double density = 0.0;                 // kg/m^3 used
  double mass = 0.0;                    // kg
  Eigen::Vector3d centerOfMass = Eigen::Vector3d::Zero();  // m, mesh frame * metersPerUnit
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();       // kg m^2 about the centre of mass,
                                                           // mesh axes (URDF ixx..izz, MJCF fullinertia)
  Eigen::Vector3d principalMoments = Eigen::Vector3d::Zero();  // kg m^2 (MJCF diaginertia)
  // Rotation taking principal axes to mesh axes: inertia = R diag(principalMoments) R^T
  // (MJCF <inertial quat="w x y z">); a proper rotation.
  Eigen::Quaterniond principalAxes = Eigen::Quaterniond::Identity();
  bool surfaceOpen = false;  // the surface had holes: the fill closed them or counted a shell
  std::vector<std::string> warnings;
};

// Throws Error for a mesh with no triangles or no extent, InvalidArgument for options out of
// range. A mesh with no enclosed volume (a single plane) gets the volume of its one-voxel-thick
// shell and a warning.
MassProperties estimateMassProperties(const Mesh& mesh, const MassOptions& options = {});

// The same body with a different mass (a user's edit in the GUI): inertia scales with the mass,
// centre and axes stay. Throws InvalidArgument for mass <= 0.
MassProperties withMass(const MassProperties& properties, double mass);

}  // namespace physics
}  // namespace sagrid
