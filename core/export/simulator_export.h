// The result of exporting one object for a simulator (MJCF or OmniGibson).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sagrid {

struct SimulatorExport {
  std::filesystem::path root;      // the folder written (complete: it is renamed into place last)
  std::filesystem::path mainFile;  // the URDF or MJCF
  std::vector<std::string> warnings;
  int visualTriangles = 0;  // triangles in the visual meshes written
  int collisionParts = 0;
  double massKg = 0.0;
};

}  // namespace sagrid
