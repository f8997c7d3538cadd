// Finding the mesh files of a folder for batch commands (extract, annotate): every file with an
// extension importMesh supports, recursively, in a stable order, each with an object id derived
// from its path (the dataset layout DIR/<id>/mesh.<ext> gives <id>).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sagrid {

inline constexpr std::size_t kMaxIdLength = 120;

struct MeshFile {
  std::filesystem::path path;
  std::string id;  // unique within one listing; valid UTF-8, at most kMaxIdLength bytes
};

// A file gives itself (id from its name, or its folder's name when it is called mesh.<ext>);
// a folder gives all supported mesh files below it, sorted by path, hidden entries skipped.
// Throws FileError when the path does not exist or is a file of an unsupported type.
std::vector<MeshFile> findMeshFiles(const std::filesystem::path& fileOrDir);

// The id a single mesh file gets: its name without extension, or its folder's name when it is
// called mesh.<ext> ("a/stove1/mesh.glb" -> "stove1").
std::string objectIdOfFile(const std::filesystem::path& meshFile);

}  // namespace sagrid
