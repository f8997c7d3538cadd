#include "core/dataset/object_source.h"

#include <cmath>
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

// The provenance.json beside `mesh` as an object; an absent or unreadable record is none.
std::optional<nlohmann::json> provenanceRecord(const fs::path& mesh) {
  const fs::path beside = mesh.parent_path() / kProvenanceRecordFile;
  std::error_code ec;
  if (!fs::is_regular_file(beside, ec)) return std::nullopt;
  try {
    nlohmann::json record = parseJsonDocument(readFileBytes(beside), beside);
    if (record.is_object()) return record;
  } catch (const FileError&) {
    // An unreadable record names no source and declares nothing: what it would say is guessed.
  }
  return std::nullopt;
}
}  // namespace

std::string objectSource(const ObjectLabels& labels, const fs::path& mesh, const std::string& fallback) {
  const auto provenance = labels.object.extra.find("provenance");
  if (provenance != labels.object.extra.end() && provenance->is_object()) {
    if (std::string repo = textOf(*provenance, "repo"); !repo.empty()) return repo;
  }
  if (const auto record = provenanceRecord(mesh)) {
    for (const char* key : {"repo", "library"})
      if (std::string source = textOf(*record, key); !source.empty()) return source;
  }
  return fallback;
}

std::optional<double> declaredMetersPerUnit(const fs::path& mesh) {
  const auto record = provenanceRecord(mesh);
  if (!record) return std::nullopt;
  const auto it = record->find("meters_per_unit");
  if (it == record->end() || !it->is_number()) return std::nullopt;
  const double value = it->get<double>();
  if (!std::isfinite(value) || value <= 0) return std::nullopt;
  return value;
}

std::optional<UpAxis> declaredUpAxis(const fs::path& mesh) {
  const auto record = provenanceRecord(mesh);
  if (!record) return std::nullopt;
  const std::string up = textOf(*record, "up");
  return up.empty() ? std::nullopt : parseUpAxis(up);
}

}  // namespace sagrid
