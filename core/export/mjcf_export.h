// Simulator export for MuJoCo: an MJCF model of the object with one <site> per affordance, named
// after its type and index as RoboCasa names its fixture sites (e.g. heatsource_0, togglebutton_1),
// in the body frame: z up, metres. The mesh is copied beside the XML.
#pragma once

#include <filesystem>

#include "core/export/omnigibson_export.h"
#include "core/labels/labels.h"

namespace sagrid {

SimulatorExport exportMjcf(const ObjectLabels& labels, const std::filesystem::path& meshPath,
                           const std::filesystem::path& outDir);

}  // namespace sagrid
