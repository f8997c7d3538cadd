// The moving parts of an MJCF export, nested as RoboCasa's fixtures nest them
// (robocasa/models/fixtures/stove.py, sink.py): each control a child body of "object" with its
// visual mesh (the part cut from the body), a collision geom that does not change as it turns
// (a cylinder about a knob's axis, a capsule along a lever), its mass, its toggle site and its
// joint(s) named `<body>_joint`, damping 1; a sink's `water` site in a child body `spout` with
// `spout_joint` (the spout is not cut from the body yet: the joint is locked to +-kLockedRange;
// MuJoCo refuses an empty range).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/export/control_geometry.h"
#include "core/export/robocasa_sites.h"

namespace sagrid::exportdetail {

struct MjcfJoint {
  std::string name;
  std::string type;  // "hinge" or "slide"
  Eigen::Vector3f axis;
  double low = 0, high = 0;  // radians or metres
};

// A tap handle's temperature turns +-45 degrees.
inline constexpr double kTemperatureRange = 0.78539816;
inline constexpr double kLockedRange = 1e-4;  // radians
// Added to a control joint's inertia (kg m^2): a knob of a few grams is otherwise near singular
// for MuJoCo ("inertia matrix too close to singular").
inline constexpr double kControlArmature = 1e-4;

// The joints of the control named `body` (its site's name): `<body>_joint`; a sink's only handle
// also turns about z for the temperature (`handle_temp_joint`).
std::vector<MjcfJoint> controlJoints(const ControlGeometry& control, const std::string& body,
                                     bool onlySinkHandle);

// Mesh assets (meshes/visual_<body>.stl) and materials for the controls with a mesh.
void writeControlAssets(std::ostringstream& xml, const std::vector<ControlGeometry>& controls,
                        const std::vector<std::string>& bodies, const std::filesystem::path& folder);

// One control's body, indented under "object"; `site` is its point's site (simulator frame).
void writeControlBody(std::ostringstream& xml, const ControlGeometry& control,
                      const std::string& body, const MjcfSite& site,
                      const std::vector<MjcfJoint>& joints);

// MuJoCo filters contacts between a body and its parent only where the parent moves; "object"
// stands still, so each control is excluded from touching it explicitly (its part is cut from
// the body, whose collision geoms cover where it sits), and from touching the other controls.
void writeContactExclusions(std::ostringstream& xml, const std::vector<std::string>& bodies);

// A site, at its position less `origin` (its body's position), coloured by affordance type.
void writeSite(std::ostringstream& xml, const MjcfSite& site, const std::string& indent,
               const Eigen::Vector3f& origin = Eigen::Vector3f::Zero());

// A water site inside its spout body (`spout`, `spout_2`, ... after the site's name).
void writeSpoutBody(std::ostringstream& xml, const MjcfSite& water);

}  // namespace sagrid::exportdetail
