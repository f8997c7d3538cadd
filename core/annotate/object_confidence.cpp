#include "core/annotate/object_confidence.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "core/annotate/annotate.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/joined.h"
#include "core/common/log.h"
#include "core/model/model_card.h"

namespace sagrid {
namespace {

constexpr double kUncalibratedScale = 0.02;  // the point confidence's own map (ExtractionSettings)
constexpr double kRidge = 1e-3;

double sigmoid(double z) { return 1.0 / (1.0 + std::exp(-z)); }

// The fit's input: the uncalibrated confidence exp(-d / 0.02) in [0, 1]. Linear in d, a few
// far-off objects (d of 0.1 and more) flattened the fit on bench val to a slope of ~0.
double signalOf(double d) { return std::exp(-std::max(0.0, d) / kUncalibratedScale); }

}  // namespace

double leastSurePointDistance(const std::vector<ModelPrediction>& predictions) {
  double worst = 0;
  for (const auto& p : predictions)
    for (const auto& point : p.points) worst = std::max(worst, static_cast<double>(point.distance));
  return worst;
}

double ConfidenceCalibration::probability(double d) const {
  if (!std::isfinite(d)) return 0;
  if (!fitted) return signalOf(d);
  return sigmoid(intercept + slope * signalOf(d));
}

AutoAcceptRow autoAcceptAt(const std::vector<double>& confidence, const std::vector<bool>& right,
                           double threshold) {
  if (confidence.empty() || confidence.size() != right.size())
    throw InvalidArgument("auto-accept: " + std::to_string(confidence.size()) +
                          " confidences for " + std::to_string(right.size()) + " outcomes");
  AutoAcceptRow row;
  row.threshold = threshold;
  std::size_t accepted = 0, correct = 0;
  for (std::size_t i = 0; i < confidence.size(); ++i)
    if (confidence[i] >= threshold) ++accepted, correct += right[i];
  row.coverage = static_cast<double>(accepted) / confidence.size();
  row.precision = accepted ? static_cast<double>(correct) / accepted
                           : std::numeric_limits<double>::quiet_NaN();
  return row;
}

ConfidenceCalibration fitConfidence(const std::vector<double>& d, const std::vector<bool>& y) {
  if (d.empty() || d.size() != y.size())
    throw InvalidArgument("confidence fit: " + std::to_string(d.size()) + " signals for " +
                          std::to_string(y.size()) + " outcomes");
  double a = 0, b = 0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    // Gradient and Hessian of the negative log-likelihood plus ridge on (a, b).
    double ga = kRidge * a, gb = kRidge * b, haa = kRidge, hab = 0, hbb = kRidge;
    for (std::size_t i = 0; i < d.size(); ++i) {
      const double x = signalOf(d[i]);
      const double p = sigmoid(a + b * x);
      const double r = p - (y[i] ? 1.0 : 0.0);
      const double w = std::max(p * (1 - p), 1e-9);
      ga += r, gb += r * x;
      haa += w, hab += w * x, hbb += w * x * x;
    }
    const double det = haa * hbb - hab * hab;
    if (std::abs(det) < 1e-12) break;
    const double da = (hbb * ga - hab * gb) / det, db = (haa * gb - hab * ga) / det;
    a -= da, b -= db;
    if (std::abs(da) + std::abs(db) < 1e-9) break;
  }
  ConfidenceCalibration c;
  c.fitted = true;
  c.intercept = a;
  c.slope = b;
  c.objects = d.size();
  c.oneKeyShare = static_cast<double>(std::count(y.begin(), y.end(), true)) / d.size();
  for (double signal : d) c.measuredConfidence.push_back(c.probability(signal));
  c.measuredRight = y;
  return c;
}

nlohmann::json toJson(const ConfidenceCalibration& c) {
  return {{"schema", "sagrid.confidence/1"},
          {"signal", "x = exp(-d / 0.02), d the largest predicted distance among the object's "
                     "points (normalized units); P = 1 / (1 + exp(-(intercept + slope x)))"},
          {"target", "right with one key (every point within 5 cm, right counts)"},
          {"intercept", c.intercept},
          {"slope", c.slope},
          {"objects", c.objects},
          {"one_key_share", c.oneKeyShare},
          {"fitted_on", c.fittedOn},
          {"network_weights", c.networkWeights},
          {"measured_confidence", c.measuredConfidence},
          {"measured_right", c.measuredRight}};
}

ConfidenceCalibration readConfidenceCalibration(const std::filesystem::path& modelsDir) {
  const auto file = modelsDir / kConfidenceFile;
  ConfidenceCalibration c;
  if (!std::filesystem::exists(file)) return c;
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  try {
    const auto j = nlohmann::json::parse(text.str());
    if (j.value("schema", "") != "sagrid.confidence/1")
      throw FileError(file, "not a SAGrid confidence calibration (schema)");
    c.intercept = j.at("intercept").get<double>();
    c.slope = j.at("slope").get<double>();
    c.objects = j.value("objects", std::size_t{0});
    c.oneKeyShare = j.value("one_key_share", 0.0);
    c.fittedOn = j.value("fitted_on", "");
    if (j.contains("network_weights"))
      c.networkWeights = j.at("network_weights").get<std::map<std::string, std::string>>();
    c.measuredConfidence = j.value("measured_confidence", std::vector<double>{});
    c.measuredRight = j.value("measured_right", std::vector<bool>{});
    if (c.measuredConfidence.size() != c.measuredRight.size())
      throw FileError(file, "measured_confidence and measured_right differ in length");
    if (!std::isfinite(c.intercept) || !std::isfinite(c.slope))
      throw FileError(file, "intercept and slope must be finite");
    c.fitted = true;
  } catch (const nlohmann::json::exception& e) {
    throw FileError(file, e.what());
  }
  if (c.networkWeights.empty()) return c;
  std::map<std::string, std::string> cardWeights;
  try {
    cardWeights = model::cardWeights(modelsDir);
  } catch (const Error&) {
    return c;  // no cards beside it (a calibration written on its own) or none readable: nothing to compare
  }
  const std::vector<std::string> stale = modelsOfOtherWeights(c, cardWeights);
  if (stale.empty()) return c;
  const std::string models = joined(stale);
  logger()->warn(
      "{}: the object confidence was fitted on the predictions of other networks than this "
      "folder's cards ({}); it is not used (uncalibrated) until it is fitted again (`sagrid scorer "
      "update` or `sagrid eval --fit-confidence`)",
      file.string(), models);
  return ConfidenceCalibration{};
}

std::vector<std::string> modelsOfOtherWeights(const ConfidenceCalibration& c,
                                              const std::map<std::string, std::string>& cardWeights) {
  if (c.networkWeights.empty()) return {};
  std::set<std::string> stale;
  for (const auto& [model, weights] : c.networkWeights) {
    const auto card = cardWeights.find(model);
    if (card == cardWeights.end() || card->second != weights) stale.insert(model);
  }
  for (const auto& [model, weights] : cardWeights)
    if (!c.networkWeights.count(model)) stale.insert(model);
  return {stale.begin(), stale.end()};
}

void writeConfidenceCalibration(const std::filesystem::path& modelsDir,
                                const ConfidenceCalibration& c) {
  writeFileAtomic(modelsDir / kConfidenceFile, toJson(c).dump(2) + "\n");
}

}  // namespace sagrid
