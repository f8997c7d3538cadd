// The run manifest of a batch, OUT/annotate.jsonl: one JSON line per object and run (object,
// status, error, category, timings, model shas, shard, host), appended by every task that writes
// into OUT. Appends are whole lines written in one call under an exclusive flock on the file, so
// the lines of tasks on several nodes never interleave (as far as the file system honours flock;
// local file systems and NFS do). A reader takes the last line of each object as its state.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sagrid {

inline constexpr const char* kRunManifestFile = "annotate.jsonl";

// Throws FileError naming the file when it cannot be opened or written (full disk, read-only).
void appendManifestLine(const std::filesystem::path& manifest, const nlohmann::json& line);

// Every line of the manifest; a line that is not JSON (a torn write from a crashed older tool)
// is skipped. Throws FileError when the file cannot be read.
std::vector<nlohmann::json> readManifest(const std::filesystem::path& manifest);

// The last line of each object ("object" field) of a manifest, by object id.
std::map<std::string, nlohmann::json> latestByObject(const std::vector<nlohmann::json>& lines);

}  // namespace sagrid
