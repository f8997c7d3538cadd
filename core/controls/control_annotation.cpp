#include "core/controls/control_annotation.h"

#include "core/controls/control_pairing.h"
#include "core/controls/control_part.h"
#include "core/controls/control_record.h"
#include "core/geometry/surface_scene.h"

namespace sagrid {

std::vector<std::string> annotateControls(ObjectLabels& labels, const Mesh& mesh) {
  return annotateControls(labels, mesh, SurfaceScene(mesh));
}

std::vector<std::string> annotateControls(ObjectLabels& labels, const Mesh& mesh,
                                          const SurfaceScene& scene) {
  std::vector<std::size_t> toggles;
  std::vector<Eigen::Vector3f> points;
  for (std::size_t i = 0; i < labels.affordances.size(); ++i) {
    const AffordancePoint& p = labels.affordances[i];
    if (p.type == "togglebutton") toggles.push_back(i), points.push_back(fileToZUp(p.position, mesh.fileUp));
  }
  std::vector<std::string> warnings;
  if (toggles.empty()) return warnings;
  const ControlParts found = findControlParts(mesh, scene, points);
  const std::vector<int> drives = pairToggleButtonsWithHeatSources(labels.affordances, mesh.fileUp);
  for (std::size_t k = 0; k < toggles.size(); ++k) {
    AffordancePoint& point = labels.affordances[toggles[k]];
    if (!found.warnings[k].empty())
      warnings.push_back("toggle button point " + std::to_string(toggles[k] + 1) + ": " +
                         found.warnings[k]);
    if (point.status != AffordanceStatus::Predicted && point.extra.contains(kControlField)) continue;
    if (!found.parts[k]) {
      point.extra.erase(kControlField);
      continue;
    }
    ControlRecord record{*found.parts[k], {}};
    if (!drives.empty()) record.drives = drives[k];
    writeControlRecord(point, record, mesh.fileUp);
  }
  return warnings;
}

}  // namespace sagrid
