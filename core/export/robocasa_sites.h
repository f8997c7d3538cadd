// MJCF site names and shapes for affordance points, as RoboCasa's fixture code looks them up:
// a stove's burners are cylinder sites `burner_on_<loc>` and its knobs `knob_<loc>`, with <loc>
// from the burner layout (RoboCasa's STOVE_LOCATIONS: rear_left, rear_center, rear_right,
// front_left, front_center, front_right, center, left, right); a sink's outlet is the `water`
// site, a downward cylinder (radius 0.006 m, half-height 0.16 m, as RoboCasa's Sink001), and its
// toggle the `handle` site. Layout convention: z up, the front faces -y, left is -x (a person at
// -y looking at +y), the frame RoboCasa places fixtures in.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace sagrid::exportdetail {

struct SimulatorPoint {
  std::string type;          // affordance type, e.g. "heatsource"
  Eigen::Vector3f position;  // z up, metres
  std::optional<int> drives;  // a knob's recorded burner: the index among the heat sources
};

struct MjcfSite {
  std::string name;
  std::string shape;         // "cylinder" or "sphere"
  Eigen::Vector3f position;  // the site's centre
  Eigen::Vector2f size;      // radius and half-height (sphere: radius only)
  std::string affordanceType;
};

inline constexpr float kWaterRadius = 0.006f;
inline constexpr float kWaterHalfHeight = 0.16f;

// Burner locations for burner centres (x, y), in input order; unique names, a suffix "_2"... only
// when a layout has more burners than RoboCasa has names.
std::vector<std::string> burnerLocations(const std::vector<Eigen::Vector2f>& burners);

// One site per point, in input order. `bounds` (metres) sizes a lone burner. A stove's knobs are
// `knob_<loc>` after the burner each drives (the recorded pairing when every knob has a valid
// one, else core/controls/control_pairing.h), knobs driving nothing `knob_dummy`; a "sink"
// category (or any object with a fluid outlet) names its toggles from the left `handle`,
// `handle_temp`, then `handle_extra`. Problems with the pairing go to `warnings` when given.
std::vector<MjcfSite> robocasaSites(const std::vector<SimulatorPoint>& points,
                                    const Eigen::AlignedBox3f& bounds,
                                    const std::string& category = "",
                                    std::vector<std::string>* warnings = nullptr);

}  // namespace sagrid::exportdetail
