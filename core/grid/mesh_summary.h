// What `sagrid info` reports about a mesh file: size, frame, bounding box, normalization and
// occupancy at a grid resolution, with the time each stage took. Kept in core so the CLI only
// parses and prints, and so other front ends (GUI, batch reports) can show the same summary.
#pragma once

#include <Eigen/Geometry>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/grid/normalization.h"
#include "core/grid/voxel_grid.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

struct MeshSummary {
  std::filesystem::path path;
  std::size_t triangles = 0, vertices = 0, materials = 0, textures = 0;
  UpAxis fileUp = UpAxis::Z;
  bool fileUpDetected = false;  // chosen from the geometry (then with a confidence)
  float fileUpConfidence = 1.0f;
  std::string sha256;
  Eigen::AlignedBox3f bounds;  // mesh frame (z-up)
  Normalization normalization;
  int resolution = 0;
  std::size_t occupiedVoxels = 0;
  std::vector<std::pair<std::string, double>> stageMilliseconds;  // import, normalize, voxelize
};

MeshSummary summarizeMesh(const std::filesystem::path& path, const ImportOptions& options,
                          int resolution);

std::string formatSummary(const MeshSummary& summary);  // human-readable, several lines
nlohmann::json summaryJson(const MeshSummary& summary);

}  // namespace sagrid
