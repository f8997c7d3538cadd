// Everything below a folder, for tests asserting what a command wrote (and where it did not).
#pragma once

#include <filesystem>
#include <set>

namespace sagrid::test {

// Every entry below `dir` (files and folders, hidden ones too), recursively; empty when `dir`
// does not exist.
std::set<std::filesystem::path> entriesBelow(const std::filesystem::path& dir);

}  // namespace sagrid::test
