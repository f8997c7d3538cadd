// Helpers for tests that feed damaged files to the importer.
#pragma once

#include <filesystem>
#include <string>

#include "core/mesh/mesh_import.h"

namespace sagrid::test {

// Writes `bytes` to `path` (binary) and returns the path.
std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& bytes);

// The FileError message importMesh gives for `path`; fails the test if it imports, if the message
// does not name the file first, or if it spans more than one line.
std::string importError(const std::filesystem::path& path, const ImportOptions& options = {});

}  // namespace sagrid::test
