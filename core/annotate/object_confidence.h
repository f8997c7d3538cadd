// Object-level confidence: the probability that an object's predicted points are all right, i.e.
// that the curator accepts it with one key (every point within 5 cm of the truth, right counts;
// core/eval/curator_effort.h). It is a logistic map of one signal, the least sure predicted point
// of the object (its predicted distance d, normalized units: large when some type's best minimum is
// shallow, or when a weak extra minimum was kept), through x = exp(-d / 0.02), fitted on labelled objects (`sagrid eval
// --fit-confidence`) and stored beside the models as confidence.json. Without a fit the raw
// signal is mapped by exp(-d / 0.02) and flagged uncalibrated. The review queue orders by it
// (least sure first) and "accept automatically above X" uses it.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sagrid {

struct ModelPrediction;

inline constexpr const char* kConfidenceFile = "confidence.json";

// The signal: the largest predicted distance among the points of all predictions (0 when there are
// no points: nothing to check).
double leastSurePointDistance(const std::vector<ModelPrediction>& predictions);

// "Accept automatically above X": the share of objects at or above X and the share right among
// them (NaN when none reaches X).
struct AutoAcceptRow {
  double threshold = 0;
  double coverage = 0;
  double precision = 0;
};
// Throws InvalidArgument for mismatched sizes or no objects.
AutoAcceptRow autoAcceptAt(const std::vector<double>& confidence, const std::vector<bool>& right,
                           double threshold);

struct ConfidenceCalibration {
  bool fitted = false;
  // P(one key) = 1 / (1 + exp(-(intercept + slope * x))), x = exp(-d / 0.02) the uncalibrated map.
  double intercept = 0, slope = 0;
  std::size_t objects = 0;          // objects it was fitted on
  double oneKeyShare = 0;           // among them
  std::string fittedOn;             // dataset path(s)
  // The networks whose predictions it was fitted on: model name -> weights identity (the cards'
  // weightsIdentity()); empty for a calibration from before it was recorded.
  std::map<std::string, std::string> networkWeights;
  // The fitted objects' confidences and outcomes, so the GUI can show the precision measured at
  // any "accept automatically above X" (optimistic: measured on the data it was fitted on).
  std::vector<double> measuredConfidence;
  std::vector<bool> measuredRight;

  double probability(double leastSureDistance) const;
};

// Maximum-likelihood logistic fit (Newton's method with a small ridge, so all-right or all-wrong
// sets still give a finite map). Throws InvalidArgument for no objects or mismatched sizes.
ConfidenceCalibration fitConfidence(const std::vector<double>& leastSureDistances,
                                    const std::vector<bool>& oneKey);

nlohmann::json toJson(const ConfidenceCalibration& c);
// Reads DIR/confidence.json; an unfitted calibration when the file is absent. Throws FileError
// naming the file when it exists but is not a valid calibration. Where it records networks and the
// folder's cards differ from them (a folder mixing versions: networks retrained, added or removed,
// the calibration not), its figures say nothing of these networks: a warning naming the file and
// the models, and the calibration is not used (unfitted, flagged uncalibrated). A folder without
// readable cards is not compared.
ConfidenceCalibration readConfidenceCalibration(const std::filesystem::path& modelsDir);

// The models where `cardWeights` (model name -> weights identity) and the networks `c` was fitted
// on differ: other weights, a model it was fitted on without a card, a card it was not fitted on.
// Empty where `c` records no networks.
std::vector<std::string> modelsOfOtherWeights(const ConfidenceCalibration& c,
                                              const std::map<std::string, std::string>& cardWeights);
void writeConfidenceCalibration(const std::filesystem::path& modelsDir,
                                const ConfidenceCalibration& c);  // atomic

}  // namespace sagrid
