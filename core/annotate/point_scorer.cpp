#include "core/annotate/point_scorer.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/annotate/pass_options.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/points/point_count.h"

namespace sagrid {

namespace {
constexpr const char* kSchema = "sagrid.point_scorer/1";

bool allFinite(const std::vector<float>& v) {
  for (float x : v)
    if (!std::isfinite(x)) return false;
  return true;
}
}  // namespace

const ModelPointScorer* PointScorer::forModel(const std::string& modelName) const {
  const auto found = byModel.find(modelName);
  return found == byModel.end() ? nullptr : &found->second;
}

namespace {
std::vector<float> firstLookOf(const ModelPointScorer& scorer,
                               const std::vector<PointCandidate>& candidates) {
  std::vector<float> firstLook;
  for (const auto& c : candidates) firstLook.push_back(scorer.classifier.probability(c.features));
  return firstLook;
}
}  // namespace

std::vector<float> countDescription(const ModelPointScorer& scorer,
                                    const std::vector<PointCandidate>& candidates) {
  if (!scorer.classifier.trees || candidates.empty()) return {};
  return countFeatures(candidates, firstLookOf(scorer, candidates), scorer.choice.nmsRadius);
}

std::vector<std::size_t> chosenCandidates(const ModelPointScorer& scorer,
                                          const std::vector<PointCandidate>& candidates,
                                          const std::vector<std::vector<float>>& otherModels) {
  if (!scorer.countTrees || !scorer.classifier.trees || candidates.empty())
    return chooseCandidates(candidateProbabilities(scorer.classifier, candidates), candidates,
                            scorer.choice);
  // The first look once: the count reads it, both looks' probabilities build on it.
  const auto firstLook = firstLookOf(scorer, candidates);
  const auto p = scorer.classifier.contextTrees
                     ? bothLooks(*scorer.classifier.contextTrees, candidates, firstLook)
                     : firstLook;
  auto taken = chooseCandidates(p, candidates, scorer.choice);
  std::vector<std::vector<float>> others;
  for (const auto& other : otherModels)
    if (!other.empty()) others.push_back(other);
  const auto features =
      withOtherModels(countFeatures(candidates, firstLook, scorer.choice.nmsRadius), others);
  const PointChoice ranking{0.0f, 0.0f, scorer.choice.nmsRadius, PointChoice{}.copyThreshold};
  return withLearnedCount(std::move(taken), chooseCandidates(p, candidates, ranking), p,
                          candidates, scorer.choice.nmsRadius, *scorer.countTrees, features);
}

std::vector<ExtractedPoint> scoredPoints(const ModelPointScorer& scorer,
                                         const std::vector<PointCandidate>& candidates,
                                         const ExtractionSettings& extraction,
                                         const std::vector<std::vector<float>>& otherModels) {
  std::vector<ExtractedPoint> out;
  for (std::size_t i : chosenCandidates(scorer, candidates, otherModels))
    out.push_back({candidates[i].position, candidates[i].distance,
                   confidenceOf(candidates[i].distance, extraction)});
  return out;
}

std::vector<DecisionOfOtherWeights> decisionsOfOtherWeights(
    const PointScorer& scorer, const std::map<std::string, std::string>& cardWeights) {
  std::vector<DecisionOfOtherWeights> out;
  for (const auto& [model, decision] : scorer.byModel) {
    const auto card = cardWeights.find(model);
    if (!decision.networkWeights.empty() && card != cardWeights.end() &&
        decision.networkWeights != card->second)
      out.push_back({model, decision.networkWeights, card->second});
  }
  return out;
}

nlohmann::json toJson(const PointScorer& scorer) {
  nlohmann::json models = nlohmann::json::object();
  for (const auto& [name, m] : scorer.byModel) {
    nlohmann::json& model = models[name];
    model = {{"keep_threshold", m.choice.keepThreshold},
             {"add_threshold", m.choice.addThreshold},
             {"nms_radius", m.choice.nmsRadius},
             {"copy_threshold", m.choice.copyThreshold}};
    if (!m.networkWeights.empty()) model["network_weights"] = m.networkWeights;
    if (m.countTrees) model["count_trees"] = toJson(*m.countTrees);
    // Trees or the logistic regression, whichever decides.
    if (m.classifier.trees) {
      model["trees"] = toJson(*m.classifier.trees);
      if (m.classifier.contextTrees) model["context_trees"] = toJson(*m.classifier.contextTrees);
      continue;
    }
    model["mean"] = m.classifier.mean;
    model["scale"] = m.classifier.scale;
    model["weights"] = m.classifier.weights;
    model["bias"] = m.classifier.bias;
  }
  return {{"schema", kSchema},
          {"features", candidateFeatureNames()},
          {"context_features", contextFeatureNames()},
          {"count_features", countFeatureNames()},
          {"trained_on", scorer.trainedOn},
          {"passes_off", scorer.passesOff},
          {"models", models}};
}

std::optional<PointScorer> readPointScorer(const std::filesystem::path& modelsDir) {
  const auto file = modelsDir / kPointScorerFile;
  if (!std::filesystem::exists(file)) return std::nullopt;
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  PointScorer scorer;
  try {
    const auto j = nlohmann::json::parse(text.str());
    if (j.value("schema", "") != kSchema)
      throw FileError(file, "not a SAGrid point scorer (schema)");
    if (j.at("features").get<std::vector<std::string>>() != candidateFeatureNames())
      throw FileError(file, "reads other candidate features than this build computes: train it "
                            "again (sagrid scorer train)");
    if (j.contains("context_features") &&
        j.at("context_features").get<std::vector<std::string>>() != contextFeatureNames())
      throw FileError(file, "reads other context features than this build computes: train it "
                            "again (sagrid scorer train)");
    if (j.contains("count_features") &&
        j.at("count_features").get<std::vector<std::string>>() != countFeatureNames())
      throw FileError(file, "reads other count features than this build computes: train it "
                            "again (sagrid scorer train)");
    scorer.trainedOn = j.value("trained_on", "");
    try {
      scorer.passesOff = recordedPassesOff(j.value("passes_off", std::vector<std::string>{}));
    } catch (const InvalidArgument& e) {
      throw FileError(file, e.what());
    }
    const std::size_t d = candidateFeatureNames().size();
    for (const auto& [name, m] : j.at("models").items()) {
      ModelPointScorer s;
      s.choice.keepThreshold = m.at("keep_threshold").get<float>();
      s.choice.addThreshold = m.at("add_threshold").get<float>();
      s.choice.nmsRadius = m.at("nms_radius").get<float>();
      s.choice.copyThreshold = m.value("copy_threshold", PointChoice{}.copyThreshold);
      s.networkWeights = m.value("network_weights", "");
      if (m.contains("count_trees")) {
        if (!j.contains("count_features"))
          throw FileError(file, "model " + name + ": count trees without count_features");
        try {
          s.countTrees = boostedTreesFromJson(m.at("count_trees"));
        } catch (const InvalidArgument& e) {
          throw FileError(file, "model " + name + ": count_trees: " + e.what());
        }
        if (s.countTrees->features != countFeatureNames().size())
          throw FileError(file, "model " + name + ": its count trees read " +
                                    std::to_string(s.countTrees->features) + " features, not " +
                                    std::to_string(countFeatureNames().size()));
      }
      if (!std::isfinite(s.choice.keepThreshold) || !std::isfinite(s.choice.addThreshold) ||
          !std::isfinite(s.choice.nmsRadius) || !std::isfinite(s.choice.copyThreshold) ||
          s.choice.nmsRadius < 0)
        throw FileError(file, "model " + name + ": numbers must be finite (radius >= 0)");
      if (m.contains("trees")) {
        try {
          s.classifier.trees = boostedTreesFromJson(m.at("trees"));
        } catch (const InvalidArgument& e) {
          throw FileError(file, "model " + name + ": " + e.what());
        }
        if (s.classifier.trees->features != d)
          throw FileError(file, "model " + name + ": its trees read " +
                                    std::to_string(s.classifier.trees->features) + " features");
        if (m.contains("context_trees")) {
          if (!j.contains("context_features"))
            throw FileError(file, "model " + name + ": context trees without context_features");
          try {
            s.classifier.contextTrees = boostedTreesFromJson(m.at("context_trees"));
          } catch (const InvalidArgument& e) {
            throw FileError(file, "model " + name + ": context_trees: " + e.what());
          }
          if (s.classifier.contextTrees->features != d + kContextFeatureCount)
            throw FileError(file, "model " + name + ": its context trees read " +
                                      std::to_string(s.classifier.contextTrees->features) +
                                      " features, not " +
                                      std::to_string(d + kContextFeatureCount));
        }
        scorer.byModel[name] = s;
        continue;
      }
      for (const char* needsTrees : {"context_trees", "count_trees"})
        if (m.contains(needsTrees))
          throw FileError(file, "model " + name + ": " + needsTrees +
                                    " need the trees of a first look");
      s.classifier.mean = m.at("mean").get<std::vector<float>>();
      s.classifier.scale = m.at("scale").get<std::vector<float>>();
      s.classifier.weights = m.at("weights").get<std::vector<float>>();
      s.classifier.bias = m.at("bias").get<float>();
      const auto& c = s.classifier;
      if (c.mean.size() != d || c.scale.size() != d || c.weights.size() != d)
        throw FileError(file, "model " + name + ": mean, scale and weights need " +
                                  std::to_string(d) + " values each");
      if (!allFinite(c.mean) || !allFinite(c.scale) || !allFinite(c.weights) ||
          !std::isfinite(c.bias))
        throw FileError(file, "model " + name + ": numbers must be finite");
      for (float scale : c.scale)
        if (scale <= 0) throw FileError(file, "model " + name + ": scales must be positive");
      scorer.byModel[name] = s;
    }
  } catch (const nlohmann::json::exception& e) {
    throw FileError(file, e.what());
  }
  return scorer;
}

void writePointScorer(const std::filesystem::path& modelsDir, const PointScorer& scorer) {
  // One line: the trees are thousands of small arrays.
  writeFileAtomic(modelsDir / kPointScorerFile, toJson(scorer).dump() + "\n");
}

}  // namespace sagrid
