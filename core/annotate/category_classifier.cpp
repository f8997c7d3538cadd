#include "core/annotate/category_classifier.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>

#include "core/annotate/name_weight_fit.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/features/feature_grid.h"
#include "core/geometry/part_statistics.h"
#include "core/grid/top_relief.h"

namespace sagrid {

namespace {
constexpr const char* kFormat = "sagrid.category_classifier";
constexpr int kVersion = 1;
// Standardized values beyond this say "far off" already; clamping keeps one odd dimension of a
// new mesh (and its square) from deciding alone.
constexpr double kClamp = 6.0;

// The class order: known categories sorted, "none" last (so a file reads the same every run).
std::vector<std::string> classOrder(const std::vector<CategorySample>& samples) {
  std::vector<std::string> known;
  bool none = false;
  for (const auto& s : samples) {
    const std::string c = categoryClass(s.category);
    if (c == kRejectedCategory) none = true;
    else if (std::find(known.begin(), known.end(), c) == known.end()) known.push_back(c);
  }
  std::sort(known.begin(), known.end());
  if (none) known.push_back(kRejectedCategory);
  return known;
}

std::string contentSha(const nlohmann::json& j) {
  nlohmann::json copy = j;
  copy.erase("sha256");
  return sha256Hex(copy.dump());
}
}  // namespace

std::vector<float> categoryInputs(const ObjectDescriptor& object,
                                  const CategoryInputSet& set) {
  std::vector<float> inputs = object.descriptor;
  if (set.topRelief) inputs.insert(inputs.end(), object.topRelief.begin(), object.topRelief.end());
  if (set.partStatistics)
    inputs.insert(inputs.end(), object.partStatistics.begin(), object.partStatistics.end());
  return inputs;
}

std::vector<float> categoryInputs(const FeatureGrid& grid, const Mesh& mesh,
                                  const CategoryInputSet& set,
                                  const std::vector<ConnectedPart>* meshParts) {
  ObjectDescriptor object;
  object.descriptor = grid.descriptor;
  if (set.topRelief) object.topRelief = sagrid::topRelief(grid.voxels, grid.resolution);
  if (set.partStatistics)
    object.partStatistics = meshParts ? partStatistics(mesh, *meshParts) : partStatistics(mesh);
  return categoryInputs(object, set);
}

bool EvidenceGate::passes(const std::string& category, double evidence) const {
  const auto it = thresholds.find(category);
  return it == thresholds.end() || evidence >= it->second;
}

bool EvidenceGate::asks(double probability) const {
  return !sureProbability || probability < *sureProbability;
}

std::string categoryClass(const std::string& labelledCategory) {
  if (labelledCategory == "stove" || labelledCategory == "sink") return labelledCategory;
  return kRejectedCategory;
}

CategoryClassifier CategoryClassifier::train(const std::vector<CategorySample>& samples,
                                             const CategoryTrainingOptions& options) {
  if (samples.empty()) throw InvalidArgument("no objects to train the category classifier on");
  CategoryClassifier c;
  c.m_classes = classOrder(samples);
  if (c.m_classes.size() < 2)
    throw InvalidArgument("the category classifier needs objects of at least two classes (got only " +
                          c.m_classes.front() + ")");
  const std::size_t d = samples.front().descriptor.size();
  if (d == 0) throw InvalidArgument("objects have empty descriptors");
  const std::size_t n = samples.size(), k = c.m_classes.size();
  Eigen::MatrixXd x(n, d);
  Eigen::MatrixXd y = Eigen::MatrixXd::Zero(n, k);
  std::map<std::string, int> counts;
  for (std::size_t i = 0; i < n; ++i) {
    if (samples[i].descriptor.size() != d)
      throw InvalidArgument("object " + samples[i].id + " has a descriptor of size " +
                            std::to_string(samples[i].descriptor.size()) + ", others " +
                            std::to_string(d));
    for (std::size_t j = 0; j < d; ++j) x(i, j) = samples[i].descriptor[j];
    const std::string cls = categoryClass(samples[i].category);
    const auto at = std::find(c.m_classes.begin(), c.m_classes.end(), cls) - c.m_classes.begin();
    y(i, at) = 1.0;
    ++counts[cls];
  }
  // Standardize; near-constant dimensions get a floor so a new object cannot blow them up.
  c.m_centre.resize(d);
  c.m_scale.resize(d);
  for (std::size_t j = 0; j < d; ++j) {
    const double mean = x.col(j).mean();
    const double sd = std::sqrt((x.col(j).array() - mean).square().mean());
    c.m_centre[j] = static_cast<float>(mean);
    c.m_scale[j] = static_cast<float>(std::max(sd, 1e-3));
    x.col(j) = ((x.col(j).array() - mean) / c.m_scale[j]).cwiseMax(-kClamp).cwiseMin(kClamp);
  }
  c.m_quadratic = options.quadratic && !options.trees;
  c.m_inputs = options.inputs;
  if (c.m_quadratic) {
    Eigen::MatrixXd expanded(n, 2 * d);
    expanded << x, x.array().square().matrix();
    x = expanded;
  }
  const std::size_t inputs = static_cast<std::size_t>(x.cols());
  // Class-balanced sample weights (distractors and categories come in different numbers).
  Eigen::VectorXd w(n);
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Index cls;
    y.row(i).maxCoeff(&cls);
    w(i) = samples[i].weight * static_cast<double>(n) /
           (static_cast<double>(k) * counts[c.m_classes[cls]]);
  }
  w /= w.sum();
  c.m_threshold = options.threshold;
  nlohmann::json objects = nlohmann::json::object();
  for (const auto& [cls, count] : counts) objects[cls] = count;
  c.training["objects"] = objects;
  c.training["top_relief"] = options.inputs.topRelief;
  c.training["part_statistics"] = options.inputs.partStatistics;
  if (options.inputs.fileName) {
    std::vector<std::pair<std::vector<std::string>, std::string>> named;
    for (const auto& s : samples)
      if (s.publishedName) named.emplace_back(s.nameWords, categoryClass(s.category));
    c.m_names = NameEvidence::count(named, c.m_classes);
    c.training["file_name"] = true;
    c.training["named_objects"] = c.m_names.namedObjects();
    if (options.nameWeight) {
      c.m_names.setWeight(*options.nameWeight);
      c.training["file_name_weight"] = {{"weight", *options.nameWeight}, {"fixed", true}};
    } else {
      const NameWeightFit weight = fitNameWeightBySource(samples, options, c.m_classes);
      c.m_names.setWeight(weight.weight);
      c.training["file_name_weight"] = weight.toJson();
    }
  }
  if (options.trees) {
    std::vector<std::vector<float>> rows(n, std::vector<float>(inputs));
    std::vector<float> weight(n);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < inputs; ++j) rows[i][j] = static_cast<float>(x(i, j));
      weight[i] = static_cast<float>(w(i) * static_cast<double>(n));
    }
    for (std::size_t a = 0; a < k; ++a) {
      std::vector<bool> positive(n);
      for (std::size_t i = 0; i < n; ++i) positive[i] = y(i, a) > 0;
      c.m_trees.push_back(fitBoostedTrees(rows, positive, weight, options.boosting));
    }
    c.training["trees"] = {{"rounds", options.boosting.rounds}, {"depth", options.boosting.depth}};
    if (options.boosting.rowShare < 1 || options.boosting.featureShare < 1) {
      c.training["trees"]["row_share"] = options.boosting.rowShare;
      c.training["trees"]["feature_share"] = options.boosting.featureShare;
      c.training["trees"]["seed"] = options.boosting.seed;
    }
    return c;
  }
  // Step size from the curvature bound of the weighted softmax loss (0.5 lambda_max(X^T W X)),
  // found by power iteration: plain gradient descent then converges without tuning.
  Eigen::MatrixXd xtwx = x.transpose() * w.asDiagonal() * x;
  Eigen::VectorXd v = Eigen::VectorXd::Ones(inputs).normalized();
  double lambda = 1.0;
  for (int it = 0; it < 100; ++it) {
    Eigen::VectorXd next = xtwx * v;
    lambda = next.norm();
    if (lambda <= 0) break;
    v = next / lambda;
  }
  const double step = options.learningRate / (0.5 * std::max(lambda, 1e-6) + options.l2);
  Eigen::MatrixXd weights = Eigen::MatrixXd::Zero(k, inputs);
  Eigen::VectorXd bias = Eigen::VectorXd::Zero(k);
  for (int it = 0; it < options.iterations; ++it) {
    Eigen::MatrixXd logits = x * weights.transpose();
    logits.rowwise() += bias.transpose();
    for (std::size_t i = 0; i < n; ++i) {
      const double m = logits.row(i).maxCoeff();
      logits.row(i) = (logits.row(i).array() - m).exp();
      logits.row(i) /= logits.row(i).sum();
    }
    const Eigen::MatrixXd residual = w.asDiagonal() * (logits - y);  // n x k
    weights -= step * (residual.transpose() * x + options.l2 * weights);
    bias -= step * residual.colwise().sum().transpose();
  }
  c.m_weights.assign(k, std::vector<double>(inputs));
  c.m_bias.assign(k, 0.0);
  for (std::size_t a = 0; a < k; ++a) {
    c.m_bias[a] = bias(a);
    for (std::size_t j = 0; j < inputs; ++j) c.m_weights[a][j] = weights(a, j);
  }
  c.training["l2"] = options.l2;
  c.training["iterations"] = options.iterations;
  c.training["quadratic"] = options.quadratic;
  return c;
}

std::vector<double> CategoryClassifier::probabilities(
    const std::vector<float>& descriptor, const std::vector<std::string>& nameWords) const {
  return withNameEvidence(shapeProbabilities(descriptor), nameWords);
}

std::vector<double> CategoryClassifier::withNameEvidence(
    std::vector<double> p, const std::vector<std::string>& nameWords) const {
  if (!m_inputs.fileName || m_names.empty()) return p;
  return nameWeighted(std::move(p), m_names.logLikelihoods(nameWords), m_names.weight());
}

std::vector<double> CategoryClassifier::shapeProbabilities(
    const std::vector<float>& descriptor) const {
  if (descriptor.size() != m_centre.size())
    throw InvalidArgument("descriptor of size " + std::to_string(descriptor.size()) +
                          " for a category classifier trained on size " +
                          std::to_string(m_centre.size()));
  const std::vector<double> in = inputs(descriptor);
  if (!m_trees.empty()) {
    const std::vector<float> row(in.begin(), in.end());
    std::vector<double> p(m_classes.size());
    double sum = 0;
    for (std::size_t a = 0; a < m_classes.size(); ++a)
      sum += (p[a] = 1.0 / (1.0 + std::exp(-static_cast<double>(m_trees[a].score(row)))));
    for (double& v : p) v /= sum;
    return p;
  }
  std::vector<double> logits(m_classes.size());
  for (std::size_t a = 0; a < m_classes.size(); ++a) {
    double z = m_bias[a];
    for (std::size_t j = 0; j < in.size(); ++j) z += m_weights[a][j] * in[j];
    logits[a] = z;
  }
  const double m = *std::max_element(logits.begin(), logits.end());
  double sum = 0;
  for (double& z : logits) sum += (z = std::exp(z - m));
  for (double& z : logits) z /= sum;
  return logits;
}

std::vector<double> CategoryClassifier::inputs(const std::vector<float>& descriptor) const {
  const std::size_t d = m_centre.size();
  std::vector<double> out(m_quadratic ? 2 * d : d);
  for (std::size_t j = 0; j < d; ++j) {
    const double z = std::clamp((descriptor[j] - m_centre[j]) / static_cast<double>(m_scale[j]),
                                -kClamp, kClamp);
    out[j] = z;
    if (m_quadratic) out[d + j] = z * z;
  }
  return out;
}

CategoryDecision CategoryClassifier::classify(const std::vector<float>& descriptor,
                                              const std::vector<std::string>& nameWords) const {
  return classify(descriptor, nameWords, m_threshold);
}

CategoryDecision CategoryClassifier::classify(const CategorySample& s) const {
  return classify(s.descriptor, s.nameWords);
}

CategoryClassifier::Verdict CategoryClassifier::verdict(const std::vector<double>& p,
                                                        double threshold) const {
  Verdict v;
  double bestAny = -1;
  std::string argmax;
  for (std::size_t a = 0; a < m_classes.size(); ++a) {
    if (p[a] > bestAny) bestAny = p[a], argmax = m_classes[a];
    if (m_classes[a] != kRejectedCategory && p[a] > v.score) v.score = p[a], v.best = m_classes[a];
  }
  v.rejected = argmax == kRejectedCategory || v.score < threshold;
  return v;
}

CategoryDecision CategoryClassifier::classify(const std::vector<float>& descriptor,
                                              const std::vector<std::string>& nameWords,
                                              double threshold) const {
  const auto shape = shapeProbabilities(descriptor);
  const auto p = withNameEvidence(shape, nameWords);
  CategoryDecision out;
  for (std::size_t a = 0; a < m_classes.size(); ++a) {
    out.probabilities[m_classes[a]] = p[a];
    out.shapeProbabilities[m_classes[a]] = shape[a];
  }
  const Verdict decided = verdict(p, threshold), byShape = verdict(shape, threshold);
  out.score = decided.score;
  out.best = decided.best;
  out.rejected = decided.rejected;
  out.shapeCategory = byShape.rejected ? kRejectedCategory : byShape.best;
  if (m_inputs.fileName) {
    out.nameWords = m_names.knownWords(nameWords);
    out.nameWeight = m_names.weight();
  }
  out.category = out.rejected ? kRejectedCategory : out.best;
  return out;
}

void CategoryClassifier::save(const std::filesystem::path& file) const {
  nlohmann::json j;
  j["format"] = kFormat;
  j["version"] = kVersion;
  j["classes"] = m_classes;
  j["threshold"] = m_threshold;
  j["feature_backend"] = featureBackend;
  j["feature_config_hash"] = featureConfigHash;
  j["grid_resolution"] = gridResolution;
  j["descriptor_size"] = m_centre.size();
  j["quadratic"] = m_quadratic;
  j["top_relief"] = m_inputs.topRelief;
  j["part_statistics"] = m_inputs.partStatistics;
  if (m_inputs.fileName) j["file_name"] = m_names.toJson();
  j["centre"] = m_centre;
  j["scale"] = m_scale;
  if (m_trees.empty()) {
    j["weights"] = m_weights;
    j["bias"] = m_bias;
  } else {
    j["trees"] = nlohmann::json::array();
    for (const auto& t : m_trees) j["trees"].push_back(toJson(t));
  }
  j["training"] = training;
  if (!evidence.empty()) {
    j["evidence"] = {{"thresholds", evidence.thresholds},
                     {"models", evidence.modelShas},
                     {"record", evidence.record}};
    if (evidence.sureProbability) j["evidence"]["sure_probability"] = *evidence.sureProbability;
  }
  j["sha256"] = contentSha(j);
  writeFileAtomic(file, j.dump(1) + "\n");
}

CategoryClassifier CategoryClassifier::load(const std::filesystem::path& file) {
  const std::string text = readFileBytes(file);
  CategoryClassifier c;
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    if (j.value("format", "") != kFormat)
      throw FileError(file, std::string("not a category classifier (format is not \"") + kFormat + "\")");
    if (j.at("version").get<int>() != kVersion)
      throw FileError(file, "category classifier version " + j.at("version").dump() +
                                " is not supported (expected " + std::to_string(kVersion) + ")");
    if (j.contains("sha256") && j.at("sha256").get<std::string>() != contentSha(j))
      throw FileError(file, "category classifier content does not match its sha256 (edited or "
                            "truncated); retrain it with `sagrid category train`");
    c.m_classes = j.at("classes").get<std::vector<std::string>>();
    c.m_threshold = j.at("threshold").get<double>();
    c.featureBackend = j.at("feature_backend").get<std::string>();
    c.featureConfigHash = j.value("feature_config_hash", "");
    c.gridResolution = j.value("grid_resolution", 0);
    c.m_centre = j.at("centre").get<std::vector<float>>();
    c.m_scale = j.at("scale").get<std::vector<float>>();
    c.m_quadratic = j.value("quadratic", false);
    c.m_inputs.topRelief = j.value("top_relief", false);
    c.m_inputs.partStatistics = j.value("part_statistics", false);
    if (j.contains("file_name")) {
      c.m_inputs.fileName = true;
      try {
        c.m_names = NameEvidence::fromJson(j.at("file_name"));
      } catch (const InvalidArgument& e) {
        throw FileError(file, std::string("malformed category classifier: ") + e.what());
      }
    }
    if (j.contains("trees")) {
      for (const auto& t : j.at("trees")) {
        try {
          c.m_trees.push_back(boostedTreesFromJson(t));
        } catch (const InvalidArgument& e) {
          throw FileError(file, std::string("malformed category classifier: ") + e.what());
        }
      }
    } else {
      c.m_weights = j.at("weights").get<std::vector<std::vector<double>>>();
      c.m_bias = j.at("bias").get<std::vector<double>>();
    }
    c.training = j.value("training", nlohmann::json::object());
    if (j.contains("evidence")) {
      const auto& e = j.at("evidence");
      c.evidence.thresholds = e.at("thresholds").get<std::map<std::string, double>>();
      c.evidence.modelShas = e.at("models").get<std::map<std::string, std::string>>();
      c.evidence.record = e.value("record", nlohmann::json::object());
      if (e.contains("sure_probability"))
        c.evidence.sureProbability = e.at("sure_probability").get<double>();
    }
  } catch (const nlohmann::json::exception& e) {
    throw FileError(file, std::string("malformed category classifier: ") + e.what());
  }
  const std::size_t d = c.m_centre.size(), k = c.m_classes.size();
  const std::size_t inputs = c.m_quadratic ? 2 * d : d;
  bool ok = d > 0 && k >= 2 && c.m_scale.size() == d &&
            (c.m_trees.empty() ? c.m_weights.size() == k && c.m_bias.size() == k
                               : c.m_trees.size() == k);
  for (const auto& row : c.m_weights) ok = ok && row.size() == inputs;
  for (const auto& t : c.m_trees) ok = ok && t.features == inputs;
  for (float s : c.m_scale) ok = ok && s > 0;
  for (const auto& [category, t] : c.evidence.thresholds)
    if (!std::isfinite(t) || t < 0 || t > 1)
      throw FileError(file, "malformed category classifier: evidence threshold of \"" + category +
                                "\" is not a confidence in [0, 1]");
  if (c.evidence.sureProbability &&
      !(*c.evidence.sureProbability > 0 && *c.evidence.sureProbability <= 1))
    throw FileError(file,
                    "malformed category classifier: evidence sure_probability is not a "
                    "probability in (0, 1]");
  if (c.m_inputs.fileName && c.m_names.classes() != c.m_classes)
    throw FileError(file,
                    "malformed category classifier: its file-name evidence names other "
                    "classes than the classifier");
  if (!ok)
    throw FileError(file, "malformed category classifier: classes, centre, scale, weights and bias "
                          "(or trees) do not agree in size");
  return c;
}

}  // namespace sagrid
