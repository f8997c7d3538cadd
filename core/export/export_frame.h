// Shared by the simulator exporters: the object's id, label positions in the simulator frame
// (z up, metres), and copying the mesh with the files it references (OBJ materials, textures).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "core/labels/labels.h"

namespace sagrid::exportdetail {

std::string objectId(const ObjectLabels& labels, const std::filesystem::path& meshPath);
// The rotation that stands the mesh file up in a z-up world (object.up -> +z): URDF
// "roll pitch yaw" and an MJCF "w x y z" quaternion ("" when the file is already z-up).
std::string uprightRollPitchYaw(const ObjectLabels& labels);
std::string uprightQuaternion(const ObjectLabels& labels);
// Label position (mesh file frame) -> z-up metres.
Eigen::Vector3f toSimulatorFrame(const ObjectLabels& labels, const Eigen::Vector3f& filePosition);
// Copies `mesh` to dir/<newName or its own name> plus the .mtl files and textures an OBJ names
// (kept at their relative paths). Returns the copied mesh's path.
std::filesystem::path copyMeshWithDependencies(const std::filesystem::path& mesh,
                                               const std::filesystem::path& dir,
                                               const std::string& newName = "");
std::string formatNumber(double value);

}  // namespace sagrid::exportdetail
