// Shared by the simulator exporters: the object's id, label positions in the simulator frame
// (z up, metres), numbers as text (refusing non-finite ones), and copying a mesh with the files
// it references (OBJ materials, textures), each resolved inside the mesh's own folder.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "core/labels/labels.h"

namespace sagrid::exportdetail {

// object.id, else the mesh's name (its folder's name for DIR/mesh.<ext>). Raw text from data:
// make it a file name with safeFileName before building a path from it.
std::string objectId(const ObjectLabels& labels, const std::filesystem::path& meshPath);
// Label position (mesh file frame, file units) -> z-up metres.
Eigen::Vector3f toSimulatorFrame(const ObjectLabels& labels, const Eigen::Vector3f& filePosition,
                                 double metersPerUnit);
// The existing files an OBJ mesh references (its mtllib files and their textures), each resolved
// with resolveContained inside the mesh's folder: one that leaves it (absolute, "../", a link) is
// refused with a FileError naming the OBJ or MTL. Empty for other formats.
std::vector<std::filesystem::path> containedMeshReferences(const std::filesystem::path& mesh);
// Copies `mesh` to dir/<newName or its own name> plus the .mtl files and textures an OBJ names
// (kept at their relative paths). References are resolved with resolveContained: one that leaves
// the mesh's folder (absolute, "../", a link) is refused with a FileError naming the OBJ or MTL.
// Returns the copied mesh's path.
std::filesystem::path copyMeshWithDependencies(const std::filesystem::path& mesh,
                                               const std::filesystem::path& dir,
                                               const std::string& newName = "");
// "%.6g"; throws Error for NaN or infinity (validation upstream must have caught them).
std::string formatNumber(double value);
// "x y z" with formatNumber.
std::string formatVector(const Eigen::Vector3d& v);

}  // namespace sagrid::exportdetail
