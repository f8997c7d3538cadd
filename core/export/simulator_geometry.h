// Everything a simulator export writes about an object's shape, computed once: the mesh loaded
// through the same importer as every other command (import before export: what cannot be loaded
// is refused), stood up (z up) and scaled to metres; its moving control parts (control_geometry.h)
// and the body less them; the body's visual parts and collision parts (none, one hull or the
// convex decomposition); the whole object's mass and inertia (the curator's mass from labels when
// set); and the warnings a user should see.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/export/control_geometry.h"
#include "core/export/export_options.h"
#include "core/export/robocasa_sites.h"
#include "core/export/visual_parts.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh.h"
#include "core/physics/convex_part.h"
#include "core/physics/mass_properties.h"

namespace sagrid::exportdetail {

struct SimulatorGeometry {
  Mesh mesh;  // z up, metres; the whole object
  Mesh body;  // the mesh less its moving control parts (the visual and collision geometry)
  std::vector<ControlGeometry> controls;  // ExportOptions::articulatedControls
  Eigen::AlignedBox3f bounds;
  double metersPerUnit = 1.0;
  std::vector<MeshPart> visualParts;
  std::vector<physics::ConvexPart> collisionParts;
  physics::MassProperties mass;
  bool massFromLabels = false;  // object.mass_kg was set
  std::vector<std::string> warnings;
};

// `labelsPath` is named in errors about labels fields (may be empty for unsaved labels). Throws
// FileError for a mesh the importer refuses and for unusable numbers in the labels.
SimulatorGeometry buildSimulatorGeometry(const ObjectLabels& labels,
                                         const std::filesystem::path& meshPath,
                                         const std::filesystem::path& labelsPath,
                                         const ExportOptions& options);

// One site per point, named as RoboCasa looks them up (robocasa_sites.h), with the controls'
// recorded pairings; the names of the controls' bodies and links too. Pairing problems go to
// `warnings`.
std::vector<MjcfSite> simulatorSites(const ObjectLabels& labels,
                                     const SimulatorGeometry& geometry,
                                     std::vector<std::string>& warnings);

}  // namespace sagrid::exportdetail
