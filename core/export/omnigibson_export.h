// Simulator export for OmniGibson / BEHAVIOR-1K, following the rules of its own importer
// (StanfordVL/BEHAVIOR-1K, OmniGibson/omnigibson/utils/asset_conversion_utils.py; each rule is
// stated with its function in tests/core/export/omnigibson_conformance_test.cpp):
//   OUT/<category>/<model>/urdf/<model>.urdf                 base_link: visual, convex collision
//                                                            parts, mass and inertia
//   OUT/<category>/<model>/urdf/<model>_with_meta_links.urdf the same plus the meta links on fixed
//                                                            joints, as the importer builds it
//   OUT/<category>/<model>/shape/visual/<model>_base_link_visual.obj (+ .mtl, textures)
//   OUT/<category>/<model>/shape/collision/<model>_base_link_collision_<i>.obj (unit box + scale)
//   OUT/<category>/<model>/misc/metadata.json                bbox_size, base_link_offset,
//                                                            link_tags, meta_links, ...
// <model> is exactly 6 letters (omnigibson_model_name.h). The meta links live in metadata.json and
// in the _with_meta_links URDF only: the importer's _add_meta_links_to_urdf adds them to
// <model>.urdf itself, so listing them there too would duplicate every meta link. Everything is in
// OmniGibson's frame: z up, metres. The folder is renamed into place when complete.
#pragma once

#include <filesystem>
#include <string>

#include "core/export/export_options.h"
#include "core/export/simulator_export.h"
#include "core/labels/labels.h"

namespace sagrid {

// OmniGibson's meta-link type for an affordance type ("fluidsource" -> "particlesource", or
// "fluidsource" with legacyFluidSource); "" when OmniGibson has none.
std::string omnigibsonMetaLinkType(const std::string& affordanceType, bool legacyFluidSource);

// Throws FileError/InvalidArgument on unusable input; nothing is left under OUT then.
SimulatorExport exportOmniGibson(const ObjectLabels& labels, const std::filesystem::path& meshPath,
                                 const std::filesystem::path& outDir,
                                 const ExportOptions& options = {},
                                 const std::filesystem::path& labelsPath = {});

}  // namespace sagrid
