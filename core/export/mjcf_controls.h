// The moving parts of an MJCF export, nested as RoboCasa's fixtures nest them
// (robocasa/models/fixtures/stove.py, sink.py): each control a child body of "object" with its
// visual mesh (the part cut from the body), a collision geom that does not change as it turns
// (a cylinder about a knob's axis, a capsule along a lever), its mass, its toggle site and its
// joint(s) named `<body>_joint`, damping 1 (a stove's button that drives a burner: see
// writeSwitchBody); a sink's `water` site in a child body `spout` with
// `spout_joint` (the spout is not cut from the body yet: the joint is locked to +-kLockedRange;
// MuJoCo refuses an empty range).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/export/control_geometry.h"
#include "core/export/robocasa_sites.h"

namespace sagrid::exportdetail {

// Added to a control joint's inertia (kg m^2): a knob of a few grams is otherwise near singular
// for MuJoCo ("inertia matrix too close to singular").
inline constexpr double kControlArmature = 1e-4;

struct MjcfJoint {
  std::string name;
  std::string type;  // "hinge" or "slide"
  Eigen::Vector3f axis;
  double low = 0, high = 0;  // radians or metres
  double damping = kControlDamping;  // N m s/rad or N s/m
  double armature = kControlArmature;
  double frictionLoss = 0;   // N or N m: what it takes to move it at all
  double stiffness = 0, springRef = 0;  // a spring (N/m) towards springRef; none at 0
};

// A button holds where it is left (a latching switch): dry friction above its weight (a few grams)
// and below a finger's push, so it neither sinks in under gravity nor resists a press.
inline constexpr double kButtonHold = 0.5;  // N
// MuJoCo 2.2 has no gravity compensation and its dry friction creeps under a steady load, so a
// button's weight along its travel is carried by a spring this long (N/m = weight / length,
// its rest this far out): over 4 mm of travel its force changes by 0.4 %.
inline constexpr double kCarrySpringLength = 1.0;  // m
inline constexpr double kGravity = 9.81;            // m/s^2, MuJoCo's default, along -z

// A tap handle's temperature turns +-45 degrees.
inline constexpr double kTemperatureRange = 0.78539816;
inline constexpr double kLockedRange = 1e-4;  // radians

// A stove's push button or touch key that drives a burner. RoboCasa lights a burner from the
// angle of its `knob_<loc>_joint` (robocasa/models/fixtures/stove.py: Stove.update_state, between
// 0.35 rad and 2 pi - 0.35), which a press cannot give. So the press (`<body>_press_joint`, a
// slide) drives a switch: a body `<body>_switch` beside the button, with no geoms, whose hinge
// `<body>_joint` follows the press through a joint equality, a full press of kButtonTravel being
// kSwitchAngle. A pressed button then lights its burner by RoboCasa's own rule, and RoboCasa
// setting the knob's angle (Stove.set_knob_state, up to the joint's range) presses the button.
inline constexpr double kSwitchAngle = 1.57079633;  // above RoboCasa's "high" (80 degrees)
// The switch's hinge has no damping, and an armature that weighs on the press times
// (kSwitchAngle / kButtonTravel)^2 (about 1.5e5): 15 kg, so a 1 N press goes home in about a third
// of a second, and the switch is some 3,000 times heavier than the key in the equality, so an
// angle set on the knob joint (RoboCasa's reset, Stove.set_knob_state) stands and pulls the key in
// rather than the key pulling the angle back.
inline constexpr double kSwitchArmature = 1e-4;

// Whether `control` (its body `body`) is such a button: a slide whose body names a burner of
// `burnerSites` (`knob_<loc>` beside `burner_on_<loc>`).
bool pressDrivesSwitch(const ControlGeometry& control, const std::string& body,
                       const std::set<std::string>& burnerSites);

// The joints of the control named `body` (its site's name): `<body>_joint`; a sink's only handle
// also turns about z for the temperature (`handle_temp_joint`); a button that drives a switch
// slides on `<body>_press_joint` (its switch has `<body>_joint`).
std::vector<MjcfJoint> controlJoints(const ControlGeometry& control, const std::string& body,
                                     bool onlySinkHandle, bool drivesSwitch = false);

// The switch body of a button `body` that drives one (pressDrivesSwitch), indented under "object".
void writeSwitchBody(std::ostringstream& xml, const ControlGeometry& control,
                     const std::string& body);

// The joint equalities that make each switch follow its button's press; nothing for none.
void writeSwitchEqualities(std::ostringstream& xml, const std::vector<std::string>& switchedBodies);

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
