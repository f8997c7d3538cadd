#include "core/points/point_count.h"

#include <algorithm>
#include <cmath>

#include "core/common/error.h"
#include "core/points/candidate_classifier.h"

namespace sagrid {

namespace {
// The first look's probabilities of the ranking's first few, each a feature.
constexpr std::size_t kRankedProbabilities = 8;
// What withOtherModels takes from another model's countFeatures.
constexpr const char* kFromOtherModels[] = {"kept_count", "p_sum", "likely", "possible"};

// The names of countFeatures' values, in its order.
const std::vector<std::string>& ownFeatureNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = {"kept_count", "candidates"};
    for (std::size_t r = 1; r <= kRankedProbabilities; ++r) n.push_back("p" + std::to_string(r));
    for (const char* s : {"p_sum", "likely", "possible", "best_copies", "top_copies"})
      n.push_back(s);
    return n;
  }();
  return names;
}

std::size_t ownFeatureIndex(const std::string& name) {
  const auto& names = ownFeatureNames();
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}
}  // namespace

const std::vector<std::string>& countFeatureNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = ownFeatureNames();
    for (const char* name : kFromOtherModels) n.push_back(std::string("other_models_") + name);
    n.push_back("k");
    return n;
  }();
  return names;
}

std::vector<float> countFeatures(const std::vector<PointCandidate>& candidates,
                                 const std::vector<float>& firstLook, float nmsRadius) {
  if (firstLook.size() != candidates.size())
    throw InvalidArgument("point count: " + std::to_string(firstLook.size()) +
                          " probabilities for " + std::to_string(candidates.size()) +
                          " candidates");
  const PointChoice ranking{0.0f, 0.0f, nmsRadius, PointChoice{}.copyThreshold};
  const auto ranked = chooseCandidates(firstLook, candidates, ranking);
  std::vector<float> x;
  x.push_back(static_cast<float>(
      std::count_if(candidates.begin(), candidates.end(), [](const auto& c) { return c.kept; })));
  x.push_back(static_cast<float>(candidates.size()));
  for (std::size_t r = 0; r < kRankedProbabilities; ++r)
    x.push_back(r < ranked.size() ? firstLook[ranked[r]] : 0.0f);
  float sum = 0, likely = 0, possible = 0;
  for (std::size_t i : ranked) {
    sum += firstLook[i];
    likely += firstLook[i] >= 0.5f;
    possible += firstLook[i] >= 0.25f;
  }
  x.push_back(sum);
  x.push_back(likely);
  x.push_back(possible);
  std::size_t best = 0, top = 0;
  for (std::size_t r = 0; r < ranked.size() && r < 4; ++r) {
    const std::size_t copies = candidates[ranked[r]].copies.size() + 1;
    if (r == 0) best = copies;
    top = std::max(top, copies);
  }
  x.push_back(static_cast<float>(best));
  x.push_back(static_cast<float>(top));
  return x;
}

std::vector<float> withOtherModels(std::vector<float> own,
                                   const std::vector<std::vector<float>>& others) {
  const std::size_t expected = ownFeatureNames().size();
  if (own.size() != expected)
    throw InvalidArgument("point count: " + std::to_string(own.size()) + " features, expected " +
                          std::to_string(expected));
  static const std::vector<std::size_t> from = [] {
    std::vector<std::size_t> at;
    for (const char* name : kFromOtherModels) at.push_back(ownFeatureIndex(name));
    return at;
  }();
  for (std::size_t i : from) {
    float sum = 0;
    for (const auto& other : others) {
      if (other.size() != expected)
        throw InvalidArgument("point count: another model's description has " +
                              std::to_string(other.size()) + " features, expected " +
                              std::to_string(expected));
      sum += other[i];
    }
    own.push_back(sum);
  }
  return own;
}

std::vector<std::vector<float>> countRows(const std::vector<float>& features) {
  std::vector<std::vector<float>> rows;
  for (std::size_t k = 1; k <= kMaxLearnedCount; ++k) {
    rows.push_back(features);
    rows.back().push_back(static_cast<float>(k));
  }
  return rows;
}

float countAtLeast(const BoostedTrees& trees, const std::vector<float>& features, std::size_t k) {
  if (k == 0) return 1.0f;
  if (k > kMaxLearnedCount) return 0.0f;
  auto row = features;
  row.push_back(static_cast<float>(k));
  return 1.0f / (1.0f + std::exp(-trees.score(row)));
}

std::vector<std::size_t> withLearnedCount(std::vector<std::size_t> taken,
                                          const std::vector<std::size_t>& ranking,
                                          const std::vector<float>& p,
                                          const std::vector<PointCandidate>& candidates,
                                          float nmsRadius, const BoostedTrees& trees,
                                          const std::vector<float>& features) {
  for (std::size_t i : ranking) {
    if (std::find(taken.begin(), taken.end(), i) != taken.end()) continue;
    const bool near = std::any_of(taken.begin(), taken.end(), [&](std::size_t t) {
      return (candidates[t].position - candidates[i].position).norm() < nmsRadius;
    });
    if (near) continue;
    if (p[i] + countAtLeast(trees, features, taken.size() + 1) <= 1.0f) break;
    taken.push_back(i);
  }
  return taken;
}

}  // namespace sagrid
