// The folder an object's files live in. Usually the mesh's own folder; but model repositories
// (Gazebo and ROS models, many game kits) keep the mesh in a sub-folder and its textures in a
// sibling (model/meshes/stove.dae with model/materials/textures/steel.png). Files a mesh
// references are read from anywhere inside its object folder, never outside it.
#pragma once

#include <filesystem>

namespace sagrid {

// The nearest of the mesh's folder, its parent and grandparent that holds an object's own file
// (labels.json, provenance.json, Gazebo's model.config or model.sdf); the mesh's folder when none
// does.
std::filesystem::path objectFolderOf(const std::filesystem::path& meshPath);

}  // namespace sagrid
