// A model's files in a models folder: its card <model>.json, weights <model>.pt, its ensemble
// members' weights <model>.<member>.pt and what training writes beside them (<model>.loss.csv,
// ...): every regular file whose name starts with "<model>.".
#pragma once

#include <filesystem>
#include <string>

namespace sagrid::model {

// Copies the files of `modelName` (every model when empty) from `from` into `to` (created),
// replacing files of the same names (a file that is already the same one, a link to it, stays).
void copyModelFiles(const std::filesystem::path& from, const std::filesystem::path& to,
                    const std::string& modelName = "");
// Moves them instead (the source folder keeps its other files).
void moveModelFiles(const std::filesystem::path& from, const std::filesystem::path& to,
                    const std::string& modelName);

}  // namespace sagrid::model
