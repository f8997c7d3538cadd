#include "core/labels/labels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <ctime>
#include <set>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/value_ranges.h"
#include "core/io/json_file.h"

namespace sagrid {
namespace fs = std::filesystem;
using nlohmann::json;

const char* toString(AffordanceStatus status) {
  switch (status) {
    case AffordanceStatus::Predicted: return "predicted";
    case AffordanceStatus::Accepted: return "accepted";
    case AffordanceStatus::Edited: return "edited";
    case AffordanceStatus::Added: return "added";
  }
  return "predicted";
}

const char* toString(ReviewState state) {
  switch (state) {
    case ReviewState::Unreviewed: return "unreviewed";
    case ReviewState::Done: return "done";
    case ReviewState::Skipped: return "skipped";
  }
  return "unreviewed";
}

std::optional<AffordanceStatus> parseAffordanceStatus(const std::string& text) {
  for (auto s : {AffordanceStatus::Predicted, AffordanceStatus::Accepted, AffordanceStatus::Edited,
                 AffordanceStatus::Added}) {
    if (text == toString(s)) return s;
  }
  return std::nullopt;
}

std::optional<ReviewState> parseReviewState(const std::string& text) {
  for (auto s : {ReviewState::Unreviewed, ReviewState::Done, ReviewState::Skipped}) {
    if (text == toString(s)) return s;
  }
  return std::nullopt;
}

std::vector<const AffordancePoint*> ObjectLabels::ofType(const std::string& type) const {
  std::vector<const AffordancePoint*> found;
  for (const auto& a : affordances) {
    if (a.type == type) found.push_back(&a);
  }
  return found;
}

namespace {

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// Validation helpers: every failure names the file and the JSON path of the field.
class Validator {
 public:
  explicit Validator(const fs::path& path) : m_path(path) {}

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw FileError(m_path, "field '" + field + "' " + problem);
  }

  static std::string typeName(const json& j) {
    if (j.is_number()) return "a number";
    if (j.is_string()) return "a string";
    if (j.is_boolean()) return "a boolean";
    if (j.is_null()) return "null";
    if (j.is_array()) return "an array";
    return "an object";
  }

  const json& require(const json& parent, const std::string& parentField, const char* key) const {
    auto it = parent.find(key);
    if (it == parent.end()) fail(join(parentField, key), "is missing");
    return *it;
  }

  std::string string(const json& j, const std::string& field) const {
    if (!j.is_string()) fail(field, "must be a string, got " + typeName(j));
    return j.get<std::string>();
  }

  const json& object(const json& j, const std::string& field) const {
    if (!j.is_object()) fail(field, "must be an object, got " + typeName(j));
    return j;
  }

  Eigen::Vector3f vector3(const json& j, const std::string& field) const {
    if (!j.is_array() || j.size() != 3) {
      fail(field, "must be an array of 3 numbers, got " +
                      (j.is_array() ? "an array of " + std::to_string(j.size()) : typeName(j)));
    }
    Eigen::Vector3f v;
    for (int i = 0; i < 3; ++i) {
      if (!j[i].is_number()) fail(field, "must be an array of 3 numbers, got " + typeName(j[i]) +
                                             " at index " + std::to_string(i));
      const double value = j[i].get<double>();
      if (!isSaneCoordinate(value)) {
        fail(field, "holds " + j[i].dump() + " at index " + std::to_string(i) +
                        "; coordinates must be finite and within +-" + shortNumber(kMaxCoordinate));
      }
      v[i] = static_cast<float>(value);
    }
    return v;
  }

  // A finite number in [low, high].
  double number(const json& j, const std::string& field, double low, double high) const {
    if (!j.is_number()) fail(field, "must be a number, got " + typeName(j));
    const double value = j.get<double>();
    if (!(value >= low && value <= high)) {
      fail(field, "is " + j.dump() + "; it must be between " + shortNumber(low) + " and " +
                      shortNumber(high));
    }
    return value;
  }

  static std::string join(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
  }

 private:
  fs::path m_path;
};

// Copies every member of `from` whose key is not in `known` into an object.
json unknownFields(const json& from, const std::set<std::string>& known) {
  json extra = json::object();
  for (auto it = from.begin(); it != from.end(); ++it) {
    if (!known.count(it.key())) extra[it.key()] = it.value();
  }
  return extra;
}

AffordancePoint parseAffordance(const json& j, const std::string& field, const Validator& v,
                                bool legacy) {
  v.object(j, field);
  AffordancePoint a;
  a.type = v.string(v.require(j, field, "type"), field + ".type");
  if (a.type.empty()) v.fail(field + ".type", "must not be empty");
  a.position = v.vector3(v.require(j, field, "position"), field + ".position");
  if (auto it = j.find("normal"); it != j.end() && !it->is_null()) {
    a.normal = v.vector3(*it, field + ".normal");
  }
  if (auto it = j.find("status"); it != j.end()) {
    const std::string text = v.string(*it, field + ".status");
    auto status = parseAffordanceStatus(text);
    if (!status) {
      v.fail(field + ".status",
             "has unknown value '" + text + "' (expected predicted, accepted, edited or added)");
    }
    a.status = *status;
  } else if (legacy) {
    a.status = AffordanceStatus::Accepted;  // the earlier form held human ground truth only
  } else {
    v.fail(field + ".status", "is missing");
  }
  if (auto it = j.find("confidence"); it != j.end() && !it->is_null()) {
    a.confidence = static_cast<float>(v.number(*it, field + ".confidence", 0.0, 1.0));
  }
  if (auto it = j.find("source"); it != j.end()) a.source = v.string(*it, field + ".source");
  a.extra = unknownFields(j, {"type", "position", "normal", "status", "confidence", "source"});
  return a;
}

std::vector<AffordancePoint> parseAffordances(const json& root, const Validator& v, bool legacy) {
  const json& list = v.require(root, "", "affordances");
  if (!list.is_array()) v.fail("affordances", "must be an array, got " + v.typeName(list));
  if (list.size() > kMaxAffordancesPerObject) {
    v.fail("affordances", "holds " + std::to_string(list.size()) + " points; at most " +
                              std::to_string(kMaxAffordancesPerObject) + " per object are supported");
  }
  std::vector<AffordancePoint> points;
  for (std::size_t i = 0; i < list.size(); ++i) {
    points.push_back(parseAffordance(list[i], "affordances[" + std::to_string(i) + "]", v, legacy));
  }
  return points;
}

// The earlier form of shared/data/real-dev: "object" is the object's name, "category" sits at the
// top level, there is no schema and no review; everything else is kept as unknown fields.
ObjectLabels parseLegacy(const json& root, const Validator& v) {
  ObjectLabels labels;
  labels.object.id = v.string(root.at("object"), "object");
  if (auto it = root.find("category"); it != root.end()) {
    labels.object.category = v.string(*it, "category");
  }
  if (auto it = root.find("up"); it != root.end()) labels.object.up = v.string(*it, "up");
  labels.affordances = parseAffordances(root, v, /*legacy=*/true);
  labels.extra = unknownFields(root, {"object", "category", "up", "affordances"});
  return labels;
}

ObjectLabels parseCurrent(const json& root, const Validator& v) {
  ObjectLabels labels;
  const std::string schema = v.string(root.at("schema"), "schema");
  if (schema != kLabelsSchema) {
    v.fail("schema", "has unsupported version '" + schema + "' (this sagrid reads " +
                         std::string(kLabelsSchema) + ")");
  }
  const json& object = v.object(v.require(root, "", "object"), "object");
  ObjectInfo& info = labels.object;
  info.id = v.string(v.require(object, "object", "id"), "object.id");
  info.category = v.string(v.require(object, "object", "category"), "object.category");
  if (auto it = object.find("mesh"); it != object.end()) info.mesh = v.string(*it, "object.mesh");
  if (auto it = object.find("sha256"); it != object.end()) {
    info.sha256 = v.string(*it, "object.sha256");
  }
  if (auto it = object.find("up"); it != object.end()) info.up = v.string(*it, "object.up");
  if (auto it = object.find("up_confidence"); it != object.end()) {
    info.upConfidence = v.number(*it, "object.up_confidence", 0.0, 1.0);
  }
  if (auto it = object.find("meters_per_unit"); it != object.end()) {
    v.number(*it, "object.meters_per_unit", kMinMetersPerUnit, kMaxMetersPerUnit);
  }
  info.extra = unknownFields(object, {"id", "mesh", "sha256", "category", "up", "up_confidence"});

  labels.affordances = parseAffordances(root, v, /*legacy=*/false);

  if (auto it = root.find("review"); it != root.end()) {
    const json& review = v.object(*it, "review");
    if (auto s = review.find("state"); s != review.end()) {
      const std::string text = v.string(*s, "review.state");
      auto state = parseReviewState(text);
      if (!state) {
        v.fail("review.state",
               "has unknown value '" + text + "' (expected unreviewed, done or skipped)");
      }
      labels.reviewState = *state;
    }
    if (auto u = review.find("updated"); u != review.end() && !u->is_null()) {
      labels.reviewUpdated = v.string(*u, "review.updated");
    }
    labels.reviewExtra = unknownFields(review, {"state", "updated"});
  }
  labels.extra = unknownFields(root, {"schema", "object", "affordances", "review"});
  return labels;
}

json vectorJson(const Eigen::Vector3f& p) { return json::array({p.x(), p.y(), p.z()}); }

}  // namespace

ObjectLabels parseLabels(const json& root, const fs::path& pathForErrors) {
  Validator v(pathForErrors);
  if (!root.is_object()) {
    throw FileError(pathForErrors, "must hold a JSON object at the top level, got " +
                                       Validator::typeName(root));
  }
  ObjectLabels labels;
  if (root.contains("schema")) {
    labels = parseCurrent(root, v);
  } else if (root.contains("object") && root.at("object").is_string()) {
    labels = parseLegacy(root, v);
  } else if (root.contains("object")) {
    v.fail("schema", std::string("is missing (expected \"") + kLabelsSchema + "\")");
  } else {
    v.fail("object", "is missing");
  }
  static const char* const kAxes[] = {"x", "-x", "y", "-y", "z", "-z", "+x", "+y", "+z"};
  if (std::find(std::begin(kAxes), std::end(kAxes), labels.object.up) == std::end(kAxes)) {
    v.fail(root.contains("schema") ? "object.up" : "up",
           "must be one of x, -x, y, -y, z, -z, got \"" + labels.object.up + "\"");
  }
  return labels;
}

ObjectLabels readLabels(const fs::path& path) {
  ObjectLabels labels = parseLabels(readJsonFile(path), path);
  if (labels.object.mesh.empty()) {
    // The earlier form does not name its mesh; it is the mesh.* beside the labels file.
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(path.parent_path().empty() ? "." : path.parent_path(), ec)) {
      if (entry.is_regular_file() && entry.path().stem() == "mesh" &&
          entry.path().extension() != ".mtl") {
        labels.object.mesh = entry.path().filename().string();
        break;
      }
    }
  }
  return labels;
}

json toJson(const ObjectLabels& labels) {
  json root = labels.extra.is_object() ? labels.extra : json::object();
  root["schema"] = kLabelsSchema;

  json object = labels.object.extra.is_object() ? labels.object.extra : json::object();
  object["id"] = labels.object.id;
  object["mesh"] = labels.object.mesh;
  object["sha256"] = labels.object.sha256;
  object["category"] = labels.object.category;
  object["up"] = labels.object.up;
  if (labels.object.upConfidence) object["up_confidence"] = *labels.object.upConfidence;
  root["object"] = object;

  json list = json::array();
  for (const auto& a : labels.affordances) {
    json entry = a.extra.is_object() ? a.extra : json::object();
    entry["type"] = a.type;
    entry["position"] = vectorJson(a.position);
    if (a.normal) entry["normal"] = vectorJson(*a.normal);
    entry["status"] = toString(a.status);
    if (a.confidence) entry["confidence"] = *a.confidence;
    entry["source"] = a.source;
    list.push_back(entry);
  }
  root["affordances"] = list;

  json review = labels.reviewExtra.is_object() ? labels.reviewExtra : json::object();
  review["state"] = toString(labels.reviewState);
  review["updated"] = labels.reviewUpdated;
  root["review"] = review;
  return root;
}

void writeLabels(const fs::path& path, const ObjectLabels& labels) {
  // Replace rather than throw on invalid UTF-8 in strings set by code: writing must not fail
  // half-way, and the file stays valid JSON.
  const std::string text =
      toJson(labels).dump(2, ' ', false, json::error_handler_t::replace) + "\n";
  writeFileAtomic(path, text);
}

double metersPerUnit(const ObjectLabels& labels) {
  auto fromUnits = [](const json& units) -> std::optional<double> {
    if (!units.is_string()) return std::nullopt;
    const std::string u = units.get<std::string>();
    if (u == "m") return 1.0;
    if (u == "cm") return 0.01;
    if (u == "mm") return 0.001;
    if (u == "in") return 0.0254;
    if (u == "ft") return 0.3048;
    return std::nullopt;
  };
  const json& object = labels.object.extra;
  if (object.is_object()) {
    // Validated on reading; labels built in code that hold a value out of range get 1.
    if (auto it = object.find("meters_per_unit"); it != object.end() && it->is_number()) {
      const double value = it->get<double>();
      return value >= kMinMetersPerUnit && value <= kMaxMetersPerUnit ? value : 1.0;
    }
    if (auto it = object.find("units"); it != object.end()) {
      if (auto m = fromUnits(*it)) return *m;
    }
  }
  if (labels.extra.is_object()) {
    if (auto it = labels.extra.find("units"); it != labels.extra.end()) {
      if (auto m = fromUnits(*it)) return *m;
    }
  }
  return 1.0;
}

std::string currentUtcTimestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buffer;
}

}  // namespace sagrid
