#include "core/annotate/point_scorer.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/annotate/pass_options.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"

namespace sagrid {

namespace {
constexpr const char* kSchema = "sagrid.point_scorer/1";

bool allFinite(const std::vector<float>& v) {
  for (float x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// Trees (with a second look), the logistic regression, or a bag of either: whichever decides.
void writeClassifier(const CandidateClassifier& c, nlohmann::json& model) {
  if (!c.members.empty()) {
    nlohmann::json members = nlohmann::json::array();
    for (const CandidateClassifier& member : c.members) {
      nlohmann::json m = nlohmann::json::object();
      writeClassifier(member, m);
      members.push_back(std::move(m));
    }
    model["members"] = std::move(members);
    return;
  }
  if (c.trees) {
    model["trees"] = toJson(*c.trees);
    if (c.contextTrees) model["context_trees"] = toJson(*c.contextTrees);
    return;
  }
  model["mean"] = c.mean;
  model["scale"] = c.scale;
  model["weights"] = c.weights;
  model["bias"] = c.bias;
}

// `what` names the model (and member) in messages about `file`.
CandidateClassifier readClassifier(const nlohmann::json& m, const std::filesystem::path& file,
                                   const std::string& what, bool contextFeatures) {
  const std::size_t d = candidateFeatureNames().size();
  CandidateClassifier c;
  if (m.contains("members")) {
    const auto& members = m.at("members");
    if (!members.is_array() || members.empty())
      throw FileError(file, what + ": members must be a list of decisions");
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (members[i].contains("members"))
        throw FileError(file, what + ": a member of a bag is no bag");
      c.members.push_back(readClassifier(members[i], file,
                                         what + ", member " + std::to_string(i + 1),
                                         contextFeatures));
    }
    return c;
  }
  if (m.contains("trees")) {
    try {
      c.trees = boostedTreesFromJson(m.at("trees"));
    } catch (const InvalidArgument& e) {
      throw FileError(file, what + ": " + e.what());
    }
    if (c.trees->features != d)
      throw FileError(file, what + ": its trees read " + std::to_string(c.trees->features) +
                                " features");
    if (m.contains("context_trees")) {
      if (!contextFeatures)
        throw FileError(file, what + ": context trees without context_features");
      try {
        c.contextTrees = boostedTreesFromJson(m.at("context_trees"));
      } catch (const InvalidArgument& e) {
        throw FileError(file, what + ": context_trees: " + e.what());
      }
      if (c.contextTrees->features != d + kContextFeatureCount)
        throw FileError(file, what + ": its context trees read " +
                                  std::to_string(c.contextTrees->features) + " features, not " +
                                  std::to_string(d + kContextFeatureCount));
    }
    return c;
  }
  if (m.contains("context_trees"))
    throw FileError(file, what + ": context trees need the trees of a first look");
  c.mean = m.at("mean").get<std::vector<float>>();
  c.scale = m.at("scale").get<std::vector<float>>();
  c.weights = m.at("weights").get<std::vector<float>>();
  c.bias = m.at("bias").get<float>();
  if (c.mean.size() != d || c.scale.size() != d || c.weights.size() != d)
    throw FileError(file, what + ": mean, scale and weights need " + std::to_string(d) +
                              " values each");
  if (!allFinite(c.mean) || !allFinite(c.scale) || !allFinite(c.weights) || !std::isfinite(c.bias))
    throw FileError(file, what + ": numbers must be finite");
  for (float scale : c.scale)
    if (scale <= 0) throw FileError(file, what + ": scales must be positive");
  return c;
}
}  // namespace

const ModelPointScorer* PointScorer::forModel(const std::string& modelName) const {
  const auto found = byModel.find(modelName);
  return found == byModel.end() ? nullptr : &found->second;
}

std::vector<ExtractedPoint> scoredPoints(const ModelPointScorer& scorer,
                                         const std::vector<PointCandidate>& candidates,
                                         const ExtractionSettings& extraction) {
  std::vector<ExtractedPoint> out;
  const auto p = candidateProbabilities(scorer.classifier, candidates);
  for (std::size_t i : chooseCandidates(p, candidates, scorer.choice))
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
    writeClassifier(m.classifier, model);
  }
  return {{"schema", kSchema},
          {"features", candidateFeatureNames()},
          {"context_features", contextFeatureNames()},
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
    scorer.trainedOn = j.value("trained_on", "");
    try {
      scorer.passesOff = recordedPassesOff(j.value("passes_off", std::vector<std::string>{}));
    } catch (const InvalidArgument& e) {
      throw FileError(file, e.what());
    }
    for (const auto& [name, m] : j.at("models").items()) {
      ModelPointScorer s;
      s.choice.keepThreshold = m.at("keep_threshold").get<float>();
      s.choice.addThreshold = m.at("add_threshold").get<float>();
      s.choice.nmsRadius = m.at("nms_radius").get<float>();
      s.choice.copyThreshold = m.value("copy_threshold", PointChoice{}.copyThreshold);
      s.networkWeights = m.value("network_weights", "");
      if (!std::isfinite(s.choice.keepThreshold) || !std::isfinite(s.choice.addThreshold) ||
          !std::isfinite(s.choice.nmsRadius) || !std::isfinite(s.choice.copyThreshold) ||
          s.choice.nmsRadius < 0)
        throw FileError(file, "model " + name + ": numbers must be finite (radius >= 0)");
      s.classifier = readClassifier(m, file, "model " + name, j.contains("context_features"));
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
