// Gradient-boosted regression trees for a binary decision (logistic loss, Newton steps per leaf,
// as XGBoost): small, depth-limited trees over a few tens of features, fitted on thousands of
// weighted rows. The score is a log-odds; probability = sigmoid(score).
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

namespace sagrid {

struct TreeNode {
  int feature = -1;      // -1: a leaf
  float threshold = 0;   // x[feature] < threshold goes left
  int left = -1, right = -1;
  float value = 0;       // a leaf's log-odds step
};

struct BoostedTrees {
  float base = 0;  // log-odds before the trees
  std::vector<std::vector<TreeNode>> trees;
  std::size_t features = 0;
  float score(const std::vector<float>& x) const;  // log-odds
};

struct BoostingOptions {
  int rounds = 100;
  int depth = 3;
  float learningRate = 0.1f;
  float lambda = 1.0f;        // ridge on leaf values
  float minLeafHessian = 1.0f;  // a leaf holds at least this much weighted p(1-p)
  // Per feature (empty: none): +1 the score never falls as it grows, -1 never rises, 0 free
  // (XGBoost's monotone constraints: a split against the direction is not made, and each
  // subtree's leaves stay within the bounds its splits set).
  std::vector<int> monotone;
  // Stochastic gradient boosting (Friedman 2002): each tree is grown on a share of the rows and
  // may split on a share of the features, drawn anew per tree from `seed` (1 and 1: every row and
  // feature, the trees as before). Fewer rows and features per tree make the trees differ, so
  // their sum leans less on a few objects or one feature: a regularizer for small data.
  float rowShare = 1.0f;
  float featureShare = 1.0f;
  unsigned seed = 1;
};

// Throws InvalidArgument for no rows, rows of different lengths or a class without weight.
BoostedTrees fitBoostedTrees(const std::vector<std::vector<float>>& rows,
                             const std::vector<bool>& positive, const std::vector<float>& weight,
                             const BoostingOptions& options = {});

nlohmann::json toJson(const BoostedTrees& trees);
// Throws InvalidArgument naming what is wrong (a node pointing outside its tree, a feature out of
// range, a number not finite).
BoostedTrees boostedTreesFromJson(const nlohmann::json& j);

}  // namespace sagrid
