// Mesh writers: Wavefront OBJ + MTL (+ PNG textures) and binary glTF 2.0 (GLB, y-up by its spec,
// with vertex colours and embedded PNG textures). Vertices are written in the mesh's file frame
// (zUpToFile with Mesh::fileUp), so a y-up mesh is written y-up. Output bytes depend only on the
// mesh: the same mesh always gives byte-identical files. Files are written atomically. OBJ/MTL
// material names are made safe (letters, digits, '-', '_', '.', unique within the mesh), so a
// name read from a hostile file cannot add statements to the OBJ or MTL.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/mesh.h"

namespace sagrid {

// An OBJ with its companion files, in memory: name -> bytes. The first file is the .obj.
struct EncodedMeshFiles {
  std::vector<std::pair<std::string, std::string>> files;
  const std::string& mainBytes() const { return files.front().second; }
};

// `baseName` without extension, e.g. "mesh" -> mesh.obj, mesh.mtl, mesh_tex0.png.
EncodedMeshFiles encodeObj(const Mesh& mesh, const std::string& baseName);
std::string encodeGlb(const Mesh& mesh);
std::string encodePng(const Texture& texture);

// Writes every file into `dir` atomically (each file through a temporary + rename).
void writeEncodedMeshFiles(const EncodedMeshFiles& encoded, const std::filesystem::path& dir);

// Convenience: writes `path` (.obj or .glb, chosen by extension; companions beside it).
void exportMesh(const Mesh& mesh, const std::filesystem::path& path);

}  // namespace sagrid
