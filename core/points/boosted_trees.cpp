#include "core/points/boosted_trees.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <random>

#include "core/common/error.h"

namespace sagrid {

namespace {

double sigmoid(double z) { return 1.0 / (1.0 + std::exp(-std::clamp(z, -40.0, 40.0))); }

// Grows one tree. A node holds its rows once per feature, sorted by that feature (the order
// of the whole set, computed once per fit, split stably down the tree), so a split is found by
// one walk per feature instead of a sort per node.
struct Grower {
  const std::vector<std::vector<float>>& rows;
  const std::vector<double>& g;  // weighted gradient per row
  const std::vector<double>& h;  // weighted hessian per row
  const BoostingOptions& options;
  const std::vector<char>& usable;  // per feature: may this tree split on it
  std::vector<TreeNode> nodes;
  std::vector<char> goesLeft;  // per row, for the split being made

  using Orders = std::vector<std::vector<std::size_t>>;  // per feature: the node's rows, sorted

  double leafValue(double G, double H) const { return -G / (H + options.lambda); }
  double gain(double G, double H) const { return G * G / (H + options.lambda); }

  int direction(std::size_t f) const {
    return f < options.monotone.size() ? options.monotone[f] : 0;
  }

  int grow(const Orders& sorted, int depth, double lower = -INFINITY, double upper = INFINITY) {
    const std::vector<std::size_t>& idx = sorted.front();
    double G = 0, H = 0;
    for (std::size_t i : idx) G += g[i], H += h[i];
    const int self = static_cast<int>(nodes.size());
    nodes.push_back({});
    nodes[self].value = static_cast<float>(std::clamp(leafValue(G, H), lower, upper));
    if (depth >= options.depth || idx.size() < 2) return self;
    const double parent = gain(G, H);
    double bestGain = 1e-9;
    int bestFeature = -1;
    float bestThreshold = 0;
    for (std::size_t f = 0; f < sorted.size(); ++f) {
      if (!usable[f]) continue;
      const std::vector<std::size_t>& order = sorted[f];
      double GL = 0, HL = 0;
      for (std::size_t k = 0; k + 1 < order.size(); ++k) {
        GL += g[order[k]];
        HL += h[order[k]];
        const float here = rows[order[k]][f], next = rows[order[k + 1]][f];
        if (here == next) continue;
        const double HR = H - HL;
        if (HL < options.minLeafHessian || HR < options.minLeafHessian) continue;
        if (const int dir = direction(f); dir != 0) {
          const double wl = std::clamp(leafValue(GL, HL), lower, upper);
          const double wr = std::clamp(leafValue(G - GL, HR), lower, upper);
          if (dir * (wr - wl) < 0) continue;  // against the feature's direction
        }
        const double split = gain(GL, HL) + gain(G - GL, HR) - parent;
        if (split > bestGain) {
          bestGain = split;
          bestFeature = static_cast<int>(f);
          bestThreshold = 0.5f * (here + next);
        }
      }
    }
    if (bestFeature < 0) return self;
    for (std::size_t i : idx) goesLeft[i] = rows[i][bestFeature] < bestThreshold;
    Orders left(sorted.size()), right(sorted.size());
    double GL = 0, HL = 0;
    for (std::size_t f = 0; f < sorted.size(); ++f)
      for (std::size_t i : sorted[f]) (goesLeft[i] ? left[f] : right[f]).push_back(i);
    for (std::size_t i : left.front()) GL += g[i], HL += h[i];
    // A monotone split bounds its subtrees at the middle of its two sides' values.
    double leftLower = lower, leftUpper = upper, rightLower = lower, rightUpper = upper;
    if (const int dir = direction(static_cast<std::size_t>(bestFeature)); dir != 0) {
      const double wl = std::clamp(leafValue(GL, HL), lower, upper);
      const double wr = std::clamp(leafValue(G - GL, H - HL), lower, upper);
      const double middle = 0.5 * (wl + wr);
      (dir > 0 ? leftUpper : leftLower) = middle;
      (dir > 0 ? rightLower : rightUpper) = middle;
    }
    const int l = grow(left, depth + 1, leftLower, leftUpper);
    left.clear();
    const int r = grow(right, depth + 1, rightLower, rightUpper);
    nodes[self].feature = bestFeature;
    nodes[self].threshold = bestThreshold;
    nodes[self].left = l;
    nodes[self].right = r;
    return self;
  }
};

// A float written with the 7 significant digits a float holds, not the 17 of its double.
double compact(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.7g", value);
  return std::strtod(text, nullptr);
}

// A uniform draw in [0, 1) from the engine's raw output (the standard fixes mt19937's sequence,
// not its distributions', so the trees are the same on every platform).
double uniform(std::mt19937& engine) { return static_cast<double>(engine()) / 4294967296.0; }

// Per item, whether this tree takes it: a share of `count` (at least one), all for a share >= 1.
std::vector<char> drawShare(std::size_t count, float share, std::mt19937& engine) {
  std::vector<char> taken(count, 1);
  if (share >= 1.0f) return taken;
  bool any = false;
  for (auto& t : taken) any |= (t = uniform(engine) < share) != 0;
  if (!any) taken[static_cast<std::size_t>(uniform(engine) * count)] = 1;
  return taken;
}

float treeValue(const std::vector<TreeNode>& tree, const std::vector<float>& x) {
  int n = 0;
  while (tree[n].feature >= 0)
    n = x[tree[n].feature] < tree[n].threshold ? tree[n].left : tree[n].right;
  return tree[n].value;
}

}  // namespace

float BoostedTrees::score(const std::vector<float>& x) const {
  if (x.size() != features)
    throw InvalidArgument("boosted trees: " + std::to_string(x.size()) +
                          " features, the trees read " + std::to_string(features));
  float s = base;
  for (const auto& tree : trees) s += treeValue(tree, x);
  return s;
}

BoostedTrees fitBoostedTrees(const std::vector<std::vector<float>>& rows,
                             const std::vector<bool>& positive, const std::vector<float>& weight,
                             const BoostingOptions& options) {
  if (rows.empty() || rows.front().empty())
    throw InvalidArgument("boosted trees: no rows or no features to fit");
  if (positive.size() != rows.size() || weight.size() != rows.size())
    throw InvalidArgument("boosted trees: labels or weights do not match the rows");
  const std::size_t n = rows.size();
  double wPos = 0, wNeg = 0;
  for (std::size_t r = 0; r < n; ++r) {
    if (rows[r].size() != rows.front().size())
      throw InvalidArgument("boosted trees: rows with different feature counts");
    (positive[r] ? wPos : wNeg) += weight[r];
  }
  if (wPos <= 0 || wNeg <= 0) throw InvalidArgument("boosted trees: both classes need weight");
  // Weights scaled to sum n, so the leaf ridge and minimum mean the same whatever their scale.
  std::vector<double> w(n);
  for (std::size_t r = 0; r < n; ++r) w[r] = weight[r] * static_cast<double>(n) / (wPos + wNeg);
  BoostedTrees model;
  model.features = rows.front().size();
  model.base = static_cast<float>(std::log(wPos / wNeg));
  std::vector<double> score(n, model.base), g(n), h(n);
  Grower::Orders sorted(model.features, std::vector<std::size_t>(n));
  for (std::size_t f = 0; f < model.features; ++f) {
    std::iota(sorted[f].begin(), sorted[f].end(), 0);
    std::stable_sort(sorted[f].begin(), sorted[f].end(),
                     [&](std::size_t a, std::size_t b) { return rows[a][f] < rows[b][f]; });
  }
  if (!(options.rowShare > 0 && options.rowShare <= 1) ||
      !(options.featureShare > 0 && options.featureShare <= 1))
    throw InvalidArgument("boosted trees: the shares of rows and features must lie in (0, 1]");
  std::mt19937 engine(options.seed);
  for (int round = 0; round < options.rounds; ++round) {
    // A row left out of this tree weighs nothing in it: no gradient, no hessian.
    const std::vector<char> inTree = drawShare(n, options.rowShare, engine);
    const std::vector<char> usable = drawShare(model.features, options.featureShare, engine);
    for (std::size_t r = 0; r < n; ++r) {
      const double p = sigmoid(score[r]), take = inTree[r] ? w[r] : 0.0;
      g[r] = take * (p - (positive[r] ? 1.0 : 0.0));
      h[r] = take * std::max(p * (1 - p), 1e-6);
    }
    Grower grower{rows, g, h, options, usable, {}, std::vector<char>(n, 0)};
    grower.grow(sorted, 0);
    for (auto& node : grower.nodes) node.value *= options.learningRate;
    for (std::size_t r = 0; r < n; ++r) score[r] += treeValue(grower.nodes, rows[r]);
    model.trees.push_back(std::move(grower.nodes));
  }
  return model;
}

nlohmann::json toJson(const BoostedTrees& model) {
  nlohmann::json trees = nlohmann::json::array();
  for (const auto& tree : model.trees) {
    nlohmann::json nodes = nlohmann::json::array();
    for (const auto& n : tree)
      nodes.push_back({n.feature, compact(n.threshold), n.left, n.right, compact(n.value)});
    trees.push_back(nodes);
  }
  return {{"base", model.base}, {"features", model.features}, {"trees", trees}};
}

BoostedTrees boostedTreesFromJson(const nlohmann::json& j) {
  BoostedTrees model;
  model.base = j.at("base").get<float>();
  model.features = j.at("features").get<std::size_t>();
  if (!std::isfinite(model.base)) throw InvalidArgument("boosted trees: base is not finite");
  for (const auto& t : j.at("trees")) {
    std::vector<TreeNode> tree;
    for (const auto& n : t)
      tree.push_back({n.at(0).get<int>(), n.at(1).get<float>(), n.at(2).get<int>(),
                      n.at(3).get<int>(), n.at(4).get<float>()});
    const int size = static_cast<int>(tree.size());
    if (size == 0) throw InvalidArgument("boosted trees: an empty tree");
    for (int i = 0; i < size; ++i) {
      const TreeNode& n = tree[i];
      if (!std::isfinite(n.threshold) || !std::isfinite(n.value))
        throw InvalidArgument("boosted trees: a number is not finite");
      if (n.feature >= static_cast<int>(model.features))
        throw InvalidArgument("boosted trees: a node reads feature " + std::to_string(n.feature) +
                              " of " + std::to_string(model.features));
      // Children come after their parent, so every walk ends at a leaf.
      if (n.feature >= 0 && (n.left <= i || n.right <= i || n.left >= size || n.right >= size))
        throw InvalidArgument("boosted trees: a node points outside its tree");
    }
    model.trees.push_back(std::move(tree));
  }
  return model;
}

}  // namespace sagrid
