#include "core/controls/control_record.h"

#include <cmath>

#include "core/common/error.h"
#include "core/common/json_number.h"

namespace sagrid {

namespace {

nlohmann::json vectorJson(const Eigen::Vector3f& v) {
  return {jsonNumber(v.x()), jsonNumber(v.y()), jsonNumber(v.z())};
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& field,
                       const std::string& problem) {
  throw FileError(path, "affordance control." + field + ": " + problem);
}

Eigen::Vector3f readVector(const nlohmann::json& record, const std::string& field,
                           const std::filesystem::path& path) {
  const auto it = record.find(field);
  if (it == record.end() || !it->is_array() || it->size() != 3) fail(path, field, "must be [x, y, z]");
  Eigen::Vector3f v;
  for (int i = 0; i < 3; ++i) {
    if (!(*it)[i].is_number()) fail(path, field, "must hold numbers");
    v[i] = (*it)[i].get<float>();
    if (!std::isfinite(v[i])) fail(path, field, "must be finite");
  }
  return v;
}

std::string readText(const nlohmann::json& record, const std::string& field,
                     const std::filesystem::path& path) {
  const auto it = record.find(field);
  if (it == record.end() || !it->is_string()) fail(path, field, "must be text");
  return it->get<std::string>();
}

}  // namespace

nlohmann::json controlJson(const ControlRecord& record, UpAxis fileUp) {
  const ControlPart& part = record.part;
  nlohmann::json runs = nlohmann::json::array();
  for (std::size_t i = 0; i < part.triangles.size();) {
    std::size_t j = i + 1;
    while (j < part.triangles.size() && part.triangles[j] == part.triangles[j - 1] + 1) ++j;
    runs.push_back({part.triangles[i], static_cast<int>(j - i)});
    i = j;
  }
  const Eigen::Matrix3f toFile = fileToZUpRotation(fileUp).transpose();
  nlohmann::json out = {
      {"motion", toString(part.motion)},
      {"joint", isHinge(part.motion) ? "hinge" : "slide"},
      {"part", {{"origin", toString(part.origin)}, {"triangles", runs}}},
      {"axis", vectorJson(toFile * part.axis)},
      {"pivot", vectorJson(zUpToFile(part.pivot, fileUp))},
      {"radius", jsonNumber(part.radius)},
  };
  if (record.drives) out["drives"] = *record.drives;
  if (record.confirmed) out["confirmed"] = true;
  return out;
}

std::optional<ControlRecord> readControlRecord(const AffordancePoint& point, UpAxis fileUp,
                                               const std::filesystem::path& path) {
  const auto it = point.extra.find(kControlField);
  if (it == point.extra.end() || it->is_null()) return std::nullopt;
  const nlohmann::json& record = *it;
  if (!record.is_object()) fail(path, "", "must be an object");
  ControlRecord out;
  ControlPart& part = out.part;
  const auto motion = parseControlMotion(readText(record, "motion", path));
  if (!motion) fail(path, "motion", "must be knob, lever or button");
  part.motion = *motion;
  const auto partJson = record.find("part");
  if (partJson == record.end() || !partJson->is_object()) fail(path, "part", "must be an object");
  const auto origin = parsePartOrigin(readText(*partJson, "origin", path));
  if (!origin) fail(path, "part.origin", "must be connected, material, grown, disc or marked");
  part.origin = *origin;
  const auto runs = partJson->find("triangles");
  if (runs == partJson->end() || !runs->is_array()) fail(path, "part.triangles", "must be a list of [first, count]");
  if (runs->size() > kMaxControlRuns) fail(path, "part.triangles", "has too many runs");
  long long next = 0;
  for (const auto& run : *runs) {
    if (!run.is_array() || run.size() != 2 || !run[0].is_number_integer() || !run[1].is_number_integer())
      fail(path, "part.triangles", "must be a list of [first, count]");
    const long long first = run[0].get<long long>(), count = run[1].get<long long>();
    if (first < next || count < 1 || first + count > (1ll << 31) - 1)
      fail(path, "part.triangles", "runs must be ascending, apart and non-empty");
    for (long long t = first; t < first + count; ++t) part.triangles.push_back(static_cast<int>(t));
    next = first + count;
  }
  const Eigen::Matrix3f toZUp = fileToZUpRotation(fileUp);
  const Eigen::Vector3f axis = readVector(record, "axis", path);
  if (!(axis.norm() > 1e-6f)) fail(path, "axis", "must not be zero");
  part.axis = (toZUp * axis).normalized();
  part.pivot = fileToZUp(readVector(record, "pivot", path), fileUp);
  const auto radius = record.find("radius");
  if (radius != record.end()) {
    if (!radius->is_number() || !std::isfinite(radius->get<double>()) || radius->get<double>() < 0)
      fail(path, "radius", "must be a number >= 0");
    part.radius = radius->get<float>();
  }
  const auto drives = record.find("drives");
  if (drives != record.end()) {
    if (!drives->is_number_integer() || drives->get<long long>() < -1 ||
        drives->get<long long>() > static_cast<long long>(kMaxAffordancesPerObject))
      fail(path, "drives", "must be a heat source's index or -1");
    out.drives = drives->get<int>();
  }
  const auto confirmed = record.find("confirmed");
  if (confirmed != record.end()) {
    if (!confirmed->is_boolean()) fail(path, "confirmed", "must be true or false");
    out.confirmed = confirmed->get<bool>();
  }
  return out;
}

void writeControlRecord(AffordancePoint& point, const ControlRecord& record, UpAxis fileUp) {
  point.extra[kControlField] = controlJson(record, fileUp);
}

}  // namespace sagrid
