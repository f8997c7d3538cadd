// Simulator export for MuJoCo / RoboCasa: OUT/<id>/<id>.xml with
//  - the visual mesh as one binary STL per part (meshes/visual_<i>.stl, see visual_parts.h), so
//    every triangle reaches MuJoCo; visual geoms in group 1 with contype/conaffinity 0;
//  - collision geoms in group 0 from the convex decomposition (meshes/collision_<i>.stl), or one
//    hull, or none (ExportOptions::collision);
//  - the body's mass and inertia (core/physics estimate, or the curator's object.mass_kg);
//  - RoboCasa's site names (robocasa_sites.h) and a `reg_main` box geom with the bounding box;
//  - RoboCasa's nesting, worldbody > body > body name="object", with every toggle button's part a
//    child body on its joint (knob_<loc>_joint, handle_joint, ...; mjcf_controls.h) and the
//    water site in a spout body (ExportOptions::articulatedControls);
//  - <compiler angle="radian"/>; everything in the body frame: z up, metres.
// The folder is written beside its final place and renamed into it at the end.
#pragma once

#include <filesystem>

#include "core/export/export_options.h"
#include "core/export/simulator_export.h"
#include "core/labels/labels.h"

namespace sagrid {

// `labelsPath` is named in errors about labels fields. Throws FileError/InvalidArgument on
// unusable input; nothing is left under OUT then.
SimulatorExport exportMjcf(const ObjectLabels& labels, const std::filesystem::path& meshPath,
                           const std::filesystem::path& outDir, const ExportOptions& options = {},
                           const std::filesystem::path& labelsPath = {});

}  // namespace sagrid
