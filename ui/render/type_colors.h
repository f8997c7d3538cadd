// One colour per affordance type, shared by markers, panels and the legend: the BEHAVIOR-1K
// types get fixed colours (heat = orange, fluid = blue, toggle = green), others a stable hash.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace sagrid::ui {

Eigen::Vector3f typeColor(const std::string& type);
// The types offered for new points and bound to keys 1..9 (the first three are BEHAVIOR-1K's).
const std::vector<std::string>& knownTypes();

}  // namespace sagrid::ui
