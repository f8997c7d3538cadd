// Checking a folder a command wrote, for the kill -9 tests: every file must be complete and
// valid (as our own readers see it), and no temporary file may be left behind.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sagrid::test {

// Problems with the files under `folder`, one line each ("<path>: <problem>"): JSON that does
// not parse (labels.json must pass readLabels), .npz/.obj/.glb/.ply/.stl our readers refuse, XML
// whose root element is not closed, PNG without its IEND chunk. Empty when all are valid.
std::vector<std::string> invalidOutputs(const std::filesystem::path& folder);

// Files under `folder` whose names mark them as temporaries ("*.tmp-*").
std::vector<std::filesystem::path> temporaryFiles(const std::filesystem::path& folder);

// Paths of the regular files under `folder`, relative to it, sorted.
std::vector<std::string> relativeFiles(const std::filesystem::path& folder);

}  // namespace sagrid::test
