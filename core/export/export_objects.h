// Batch simulator export behind `sagrid export`: finds the objects under a path (a labels.json,
// a mesh with labels beside it, or a folder of object folders) and exports each, with names
// unique across the run. A labels file's object.mesh is resolved inside its own folder, or inside
// ExportOptions::meshRoot when the user names one (meshForLabels, core/dataset/labels_mesh.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/export/export_options.h"
#include "core/export/simulator_export.h"
#include "core/labels/labels.h"

namespace sagrid {

// `format`: "omnigibson" or "mjcf". Throws FileError when nothing labelled is found, and the
// exporters' errors otherwise (objects exported before the error stay complete).
std::vector<SimulatorExport> exportObjects(const std::filesystem::path& input,
                                           const std::string& format,
                                           const std::filesystem::path& outDir,
                                           const ExportOptions& options = {});

}  // namespace sagrid
