// Simulator export for OmniGibson / BEHAVIOR-1K: an object folder with the mesh, a URDF whose
// affordances are fixed child links named meta__<link>_<type>_<id>_0_link, and misc/metadata.json
// listing them under "meta_links". heatsource/fluidsource are points; togglebutton is a small
// sphere (OmniGibson's ToggledOn state needs a volume to touch). Positions are converted to the
// simulator's frame: z up, metres.
#pragma once

#include <filesystem>

#include "core/labels/labels.h"

namespace sagrid {

struct SimulatorExport {
  std::filesystem::path root;      // the folder written
  std::filesystem::path mainFile;  // the URDF or MJCF
  std::vector<std::string> warnings;
};

// The meta-link type for an affordance type: "point" or "sphere".
const char* omnigibsonMetaLinkKind(const std::string& affordanceType);
// Meta-link ids may not contain underscores (OmniGibson splits link names on "_"): keeps
// letters and digits only.
std::string omnigibsonId(const std::string& text);

// Writes OUT/<id>/{shape/visual/<mesh>, urdf/<id>.urdf, misc/metadata.json} atomically per file.
// `meshPath` is the object's mesh file; throws FileError/InvalidArgument on unusable input.
SimulatorExport exportOmniGibson(const ObjectLabels& labels, const std::filesystem::path& meshPath,
                                 const std::filesystem::path& outDir);

}  // namespace sagrid
