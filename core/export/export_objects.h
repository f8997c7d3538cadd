// Batch simulator export behind `sagrid export`: finds the objects under a path (a labels.json,
// a mesh with labels beside it, or a folder of object folders) and exports each.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/export/omnigibson_export.h"

namespace sagrid {

// `format`: "omnigibson" or "mjcf". Throws FileError when nothing labelled is found, and the
// exporters' errors otherwise.
std::vector<SimulatorExport> exportObjects(const std::filesystem::path& input,
                                           const std::string& format,
                                           const std::filesystem::path& outDir);

}  // namespace sagrid
