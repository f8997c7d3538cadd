// The learned point decision (issue 40): per model, a classifier over the point candidates of
// core/points/point_candidates.h (the count's points, the field's minima, the mesh's small parts)
// that decides which are affordance points and how many. It is a file of the models folder,
// point_scorer.json, trained by `sagrid scorer train` on generated and curated real objects; where
// it is present, annotate, eval and the GUI take its decision instead of the count's points
// (PassOptions::scorer). Without it, the count's points stand.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/points/candidate_classifier.h"

namespace sagrid {

inline constexpr const char* kPointScorerFile = "point_scorer.json";

struct ModelPointScorer {
  CandidateClassifier classifier;
  PointChoice choice;
  // The weights of the network whose candidates it learned from (ModelCard::weightsIdentity);
  // empty when not recorded. A models folder whose card has other weights still uses the decision
  // and says so (ModelSet::setPointScorer): its fields may no longer look like what it learned.
  std::string networkWeights;
  // How many points (core/points/point_count.h); where absent, the choice's thresholds decide.
  std::optional<BoostedTrees> countTrees;
};

struct PointScorer {
  std::map<std::string, ModelPointScorer> byModel;  // model (card) name -> its decision
  std::string trainedOn;                            // what it was trained on, for the record
  // The passes that were off when its candidates were made: off wherever it decides
  // (withLearnedDecision), so it chooses among candidates of the kind it learned from.
  std::vector<std::string> passesOff;
  // The decision for one model; nullptr where the scorer has none (its count's points stand).
  const ModelPointScorer* forModel(const std::string& modelName) const;
};

// What one model's candidates tell the learned counts of the object's other models of its
// category (core/points/point_count.h, withOtherModels): countFeatures under `scorer`'s first
// look; empty where it has no trees or there are no candidates.
std::vector<float> countDescription(const ModelPointScorer& scorer,
                                    const std::vector<PointCandidate>& candidates);

// The candidates `scorer` chooses, most probable first: its choice (PointChoice), with the
// learned count's additions where it has one (core/points/point_count.h). `otherModels`: the
// countDescription of each of the object's other models of the category (empty ones skipped).
std::vector<std::size_t> chosenCandidates(const ModelPointScorer& scorer,
                                          const std::vector<PointCandidate>& candidates,
                                          const std::vector<std::vector<float>>& otherModels = {});

// The points of one model from its candidates: the chosen candidates, most probable first, with
// their field distance and its confidence under `extraction` (as the count's points have: the
// category's evidence gate and the object confidence read them).
std::vector<ExtractedPoint> scoredPoints(const ModelPointScorer& scorer,
                                         const std::vector<PointCandidate>& candidates,
                                         const ExtractionSettings& extraction,
                                         const std::vector<std::vector<float>>& otherModels = {});

// A model whose decision learned from the candidates of other weights than its card's.
struct DecisionOfOtherWeights {
  std::string model, learnedFrom, card;  // the model; both weights identities
};
// The decisions of `scorer` that recorded weights other than `cardWeights`' (model name ->
// ModelCard::weightsIdentity); decisions without a record or without a card are not among them.
std::vector<DecisionOfOtherWeights> decisionsOfOtherWeights(
    const PointScorer& scorer, const std::map<std::string, std::string>& cardWeights);

nlohmann::json toJson(const PointScorer& scorer);
// Reads DIR/point_scorer.json; nullopt when absent. Throws FileError naming the file when it is
// not a scorer, reads other candidate features than this build computes, or has bad numbers.
std::optional<PointScorer> readPointScorer(const std::filesystem::path& modelsDir);
void writePointScorer(const std::filesystem::path& modelsDir, const PointScorer& scorer);  // atomic

}  // namespace sagrid
