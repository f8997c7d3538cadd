// Contact sheets: a grid of small renders of objects with their affordance points drawn as dots
// (red heatsource, blue fluidsource, green togglebutton, grey anything else), so a person can
// judge the variety and correctness of a dataset at a glance. Rendered on the CPU with the
// MultiViewRenderer (ray casting), no GL.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/mesh/mesh.h"

namespace sagrid::gen {

struct SheetPoint {
  std::string type;
  Eigen::Vector3f position;  // in the mesh's z-up frame (same units as Mesh::positions)
};

struct SheetItem {
  const Mesh* mesh = nullptr;
  std::vector<SheetPoint> points;
};

struct ContactSheetOptions {
  int thumbnail = 128;  // pixels per cell side
  int columns = 0;      // 0: about square
  float yawDegrees = -65.0f;
  float pitchDegrees = 28.0f;
  int viewsPerItem = 1;  // more than 1: the same object from yaw steps of 360 / views, in a row
};

Texture renderContactSheet(const std::vector<SheetItem>& items, const ContactSheetOptions& options = {});
void writeContactSheet(const std::filesystem::path& path, const std::vector<SheetItem>& items,
                       const ContactSheetOptions& options = {});

// Reads a dataset folder (manifest or object folders) and renders up to `limit` objects.
void writeDatasetContactSheet(const std::filesystem::path& datasetDir, const std::filesystem::path& pngPath,
                              int limit, const ContactSheetOptions& options = {});

}  // namespace sagrid::gen
