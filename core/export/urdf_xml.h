// URDF pieces the OmniGibson export writes for every link: origins, inertials, and collision
// parts as OmniGibson's importer stores them (generate_urdf_for_mesh: vertices divided by the
// part's bounding-box extents, the extents as the URDF mesh scale).
#pragma once

#include <Eigen/Core>
#include <string>

#include "core/physics/convex_part.h"
#include "core/physics/mass_properties.h"

namespace sagrid::exportdetail {

struct UnitBoxPart {
  std::string obj;
  Eigen::Vector3d scale;
};

UnitBoxPart unitBoxPart(const physics::ConvexPart& part);
// <origin xyz=... rpy=.../>
std::string origin(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy = Eigen::Vector3d::Zero());
// <inertial> about the centre of mass, in the link's axes, indented for a link.
std::string inertialXml(const physics::MassProperties& mass);

}  // namespace sagrid::exportdetail
