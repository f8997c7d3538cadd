// labels.json: the affordance points of one object (schema "sagrid.labels/1", DESIGN.md).
// Reading validates and names the file and field on error; the earlier, simpler form used in
// shared/data/real-dev (object is a name, no schema) is read too. Writing is atomic and keeps
// every field this version does not know about.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace sagrid {

inline constexpr const char* kLabelsSchema = "sagrid.labels/1";
// More points than any object has (a keyboard has ~100 keys); a bound for what reading costs.
inline constexpr std::size_t kMaxAffordancesPerObject = 1000;

enum class AffordanceStatus { Predicted, Accepted, Edited, Added };
enum class ReviewState { Unreviewed, Done, Skipped };

const char* toString(AffordanceStatus status);
const char* toString(ReviewState state);
std::optional<AffordanceStatus> parseAffordanceStatus(const std::string& text);
std::optional<ReviewState> parseReviewState(const std::string& text);

struct AffordancePoint {
  std::string type;                    // "heatsource", "togglebutton", "fluidsource", ...
  Eigen::Vector3f position = Eigen::Vector3f::Zero();  // mesh file's own coordinates
  std::optional<Eigen::Vector3f> normal;
  AffordanceStatus status = AffordanceStatus::Predicted;
  std::optional<float> confidence;
  std::string source;                  // e.g. "stove.heatsource@1a2b3c4d" or "human"
  nlohmann::json extra = nlohmann::json::object();  // unknown fields, kept on rewrite
};

struct ObjectInfo {
  std::string id;
  std::string mesh;       // mesh file name relative to the labels file
  std::string sha256;
  std::string category;   // "stove", "sink", ...
  std::string up = "z";   // the mesh file's up axis: "x", "-x", "y", "-y", "z" or "-z"
  // How sure the up axis is when it was detected from the geometry (0..1); unset when it was
  // given (--up) or fixed by the format. Written as object.up_confidence.
  std::optional<double> upConfidence;
  nlohmann::json extra = nlohmann::json::object();
};

struct ObjectLabels {
  ObjectInfo object;
  std::vector<AffordancePoint> affordances;
  ReviewState reviewState = ReviewState::Unreviewed;
  std::string reviewUpdated;  // ISO 8601 UTC, e.g. "2026-11-21T10:00:00Z"
  nlohmann::json extra = nlohmann::json::object();        // unknown top-level fields
  nlohmann::json reviewExtra = nlohmann::json::object();  // unknown fields of "review"

  std::vector<const AffordancePoint*> ofType(const std::string& type) const;
};

// Throws FileError naming the file and the field for every problem (missing or not a regular
// file, too large, invalid UTF-8, not JSON, nested too deep, wrong types, missing fields, unknown
// schema version, coordinates not finite or beyond kMaxCoordinate, meters_per_unit outside
// [kMinMetersPerUnit, kMaxMetersPerUnit], more than kMaxAffordancesPerObject points).
ObjectLabels readLabels(const std::filesystem::path& path);
ObjectLabels parseLabels(const nlohmann::json& json, const std::filesystem::path& pathForErrors);

nlohmann::json toJson(const ObjectLabels& labels);
void writeLabels(const std::filesystem::path& path, const ObjectLabels& labels);  // atomic

// Metres per mesh unit: object.meters_per_unit, else object.units or (earlier form) the top-level
// "units" ("m", "cm", "mm", "in", "ft"), else 1 (unknown units keep their numbers).
double metersPerUnit(const ObjectLabels& labels);

std::string currentUtcTimestamp();

}  // namespace sagrid
