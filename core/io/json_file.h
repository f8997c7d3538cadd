// Reading JSON documents that users and datasets hand us (labels.json, model cards): the size is
// bounded, the text must be UTF-8, nesting is bounded before parsing (nlohmann copies and
// compares documents recursively, so a file nested a million levels deep would overflow the
// stack later), and every problem, number overflow included, is one FileError naming the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"

namespace sagrid {

// Deeper than any document of ours (labels nest 4 levels) and far from any stack limit.
inline constexpr int kMaxJsonDepth = 64;

// Parses `text`; `source` names it in errors ("<source>: is not valid JSON: ...").
nlohmann::json parseJsonDocument(std::string_view text, const std::filesystem::path& source);

// Reads a regular file of at most `maxBytes` and parses it as above.
nlohmann::json readJsonFile(const std::filesystem::path& path,
                            std::uint64_t maxBytes = kMaxJsonFileBytes);

}  // namespace sagrid
