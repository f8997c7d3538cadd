#include "core/dataset/object_source.h"

#include <system_error>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/io/json_file.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {
std::string textOf(const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}
}  // namespace

std::string objectSource(const ObjectLabels& labels, const fs::path& mesh, const std::string& fallback) {
  const auto provenance = labels.object.extra.find("provenance");
  if (provenance != labels.object.extra.end() && provenance->is_object()) {
    if (std::string repo = textOf(*provenance, "repo"); !repo.empty()) return repo;
  }
  const fs::path beside = mesh.parent_path() / "provenance.json";
  std::error_code ec;
  if (fs::is_regular_file(beside, ec)) {
    try {
      const nlohmann::json record = parseJsonDocument(readFileBytes(beside), beside);
      if (record.is_object()) {
        for (const char* key : {"repo", "library"})
          if (std::string source = textOf(record, key); !source.empty()) return source;
      }
    } catch (const FileError&) {
      // An unreadable record names no source: the fallback stands.
    }
  }
  return fallback;
}

}  // namespace sagrid
