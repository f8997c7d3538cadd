#include "ui/render/type_colors.h"

#include <functional>

namespace sagrid::ui {

Eigen::Vector3f typeColor(const std::string& type) {
  if (type == "heatsource") return {1.00f, 0.42f, 0.12f};
  if (type == "fluidsource") return {0.20f, 0.60f, 1.00f};
  if (type == "togglebutton") return {0.30f, 0.90f, 0.35f};
  static const Eigen::Vector3f kPalette[] = {{0.95f, 0.35f, 0.75f}, {0.95f, 0.85f, 0.25f},
                                             {0.60f, 0.45f, 1.00f}, {0.25f, 0.90f, 0.85f},
                                             {0.85f, 0.55f, 0.35f}, {0.75f, 0.75f, 0.75f}};
  return kPalette[std::hash<std::string>{}(type) % 6];
}

const std::vector<std::string>& knownTypes() {
  static const std::vector<std::string> kTypes = {"heatsource", "fluidsource", "togglebutton",
                                                  "particleremover", "particleapplier"};
  return kTypes;
}

}  // namespace sagrid::ui
