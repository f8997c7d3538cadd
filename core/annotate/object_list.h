// Object lists: the text file `sagrid filter --list-out` writes and `sagrid annotate` reads
// (`--list FILE`, or a .txt / .list file as INPUT), so that a collection is filtered first and
// only the candidates are annotated. One object a line, "<id><TAB><mesh path>", or a mesh path
// alone (id as for a single file: its name, or its folder's name for mesh.<ext>). Blank lines and
// lines starting with # are ignored; relative paths are relative to the list file's folder.
#pragma once

#include <filesystem>
#include <vector>

#include "core/mesh/mesh_files.h"

namespace sagrid {

// True for a .txt or .list file (what annotate treats as an object list when given as INPUT).
bool isObjectListFile(const std::filesystem::path& path);

// Throws FileError naming the file and line for an unreadable file, a line with an empty id or
// path, and an id used twice. Mesh files are not opened (a missing one fails when annotated).
std::vector<MeshFile> readObjectList(const std::filesystem::path& listFile);

// Atomic; paths are written absolute, so the list works from any folder.
void writeObjectList(const std::filesystem::path& listFile, const std::vector<MeshFile>& files);

// The objects of INPUT: a list file (isObjectListFile), a mesh file, or every mesh of a folder
// (findMeshFiles).
std::vector<MeshFile> listObjects(const std::filesystem::path& input);

}  // namespace sagrid
