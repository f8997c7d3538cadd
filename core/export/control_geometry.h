// The moving parts of a simulator export: for every toggle button point, its control part
// (labels.json's record where the curator or annotate left one, else found on the mesh: see
// core/controls/control_part.h) cut from the body, with its mass and where it turns or slides.
// Parts that cannot move (one that would take most of the object, triangles already claimed) are
// left to the body with a warning naming the point; the point then stays a site.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/controls/control_part.h"
#include "core/controls/control_turn.h"  // kButtonTravel
#include "core/labels/labels.h"
#include "core/mesh/mesh.h"
#include "core/physics/mass_properties.h"

namespace sagrid::exportdetail {

// A solid plastic knob or lever (ABS is 1,040-1,070 kg/m^3).
inline constexpr double kControlDensity = 1050.0;
// A printed key's disc: its thickness, metres.
inline constexpr double kDiscThickness = 0.002;

struct ControlGeometry {
  std::size_t point = 0;   // index into labels.affordances
  ControlPart part;        // z up, metres
  Mesh mesh;               // the part's triangles, z up, metres, relative to part.pivot; empty: disc
  physics::MassProperties mass;  // relative to part.pivot
  std::optional<int> drives;     // the record's pairing (a heat source's index), if any
  float axisLow = 0, axisHigh = 0;  // the part's extent along part.axis from the pivot, metres
};

// How far a control moves from where the mesh shows it: a stove knob turns up to 270 degrees one
// way (RoboCasa lights its burner from 0.35 rad), a tap handle up to 90 (RoboCasa runs water from
// 0.4 rad), a button travels kButtonTravel (control_turn.h); damping as RoboCasa's fixtures. A tap's handle is turned or
// lifted, never pressed: a flat one turns about its axis.
inline constexpr double kKnobRange = 4.71238898;
inline constexpr double kHandleRange = 1.57079633;
inline constexpr double kControlDamping = 1.0;

struct ControlMotionRange {
  bool hinge = true;
  Eigen::Vector3f axis = Eigen::Vector3f::UnitZ();
  double low = 0, high = 0;  // radians or metres
};
ControlMotionRange controlMotionRange(const ControlPart& part, bool tapHandle);

struct ControlSplit {
  std::vector<ControlGeometry> controls;
  std::vector<bool> body;  // per triangle of the mesh: stays with the body
};

// `mesh` is the export's mesh (z up, metres); `metersPerUnit` scales the records (mesh units).
// Throws FileError naming `labelsPath` for a malformed record or one whose triangles the mesh
// does not have.
ControlSplit splitControls(const ObjectLabels& labels, const Mesh& mesh, double metersPerUnit,
                           const std::filesystem::path& labelsPath,
                           std::vector<std::string>& warnings);

}  // namespace sagrid::exportdetail
