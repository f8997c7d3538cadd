#include "core/annotate/model_set.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/common/error.h"

namespace sagrid {

double cosineSimilarity(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size() || a.empty()) return 0.0;
  double dot = 0, na = 0, nb = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    dot += a[i] * b[i], na += a[i] * a[i], nb += b[i] * b[i];
  return na > 0 && nb > 0 ? dot / std::sqrt(na * nb) : 0.0;
}

ModelSet ModelSet::load(const std::filesystem::path& directory) {
  std::vector<model::AffordanceModel> models;
  for (const auto& card : model::listModelCards(directory))
    models.push_back(model::AffordanceModel::load(card));
  return ModelSet(std::move(models));
}

ModelSet::ModelSet(std::vector<model::AffordanceModel> models) : m_models(std::move(models)) {
  for (const auto& m : m_models) {
    const auto& a = m_models.front().card();
    const auto& c = m.card();
    if (c.featureBackend != a.featureBackend || c.featureConfigHash != a.featureConfigHash ||
        c.gridResolution != a.gridResolution)
      throw ModelError(
          "models " + a.name + " and " + c.name +
          " need different features (backend, config or grid size); keep models of one "
          "feature setup in a folder");
  }
}

std::vector<std::string> ModelSet::categories() const {
  std::vector<std::string> out;
  for (const auto& m : m_models)
    if (std::find(out.begin(), out.end(), m.card().category) == out.end())
      out.push_back(m.card().category);
  return out;
}

std::vector<const model::AffordanceModel*> ModelSet::forCategory(
    const std::string& category) const {
  std::vector<const model::AffordanceModel*> out;
  for (const auto& m : m_models)
    if (m.card().category == category) out.push_back(&m);
  if (out.empty()) {
    std::string known;
    for (const auto& c : categories()) known += (known.empty() ? "" : ", ") + c;
    throw InvalidArgument("no model for category \"" + category + "\" (models exist for: " + known +
                          ")");
  }
  return out;
}

std::vector<float> ModelSet::categoryMean(const std::string& category) const {
  std::vector<double> sum;
  int count = 0;
  for (const auto* m : forCategory(category)) {
    const auto& d = m->card().descriptorMean;
    if (d.empty()) continue;
    if (sum.empty()) sum.assign(d.size(), 0.0);
    if (d.size() != sum.size()) continue;
    for (std::size_t i = 0; i < d.size(); ++i) sum[i] += d[i];
    ++count;
  }
  if (count == 0)
    throw ModelError("the " + category + " model cards record no descriptor mean for retrieval");
  std::vector<float> mean;
  for (double v : sum) mean.push_back(static_cast<float>(v / count));
  return mean;
}

std::vector<CategoryScore> ModelSet::rankCategories(const std::vector<float>& descriptor) const {
  std::vector<CategoryScore> scores;
  for (const auto& c : categories())
    scores.push_back({c, cosineSimilarity(descriptor, categoryMean(c))});
  std::stable_sort(
      scores.begin(), scores.end(),
      [](const CategoryScore& a, const CategoryScore& b) { return a.similarity > b.similarity; });
  return scores;
}

FeatureOptions ModelSet::featureOptions() const {
  FeatureOptions options;
  if (!m_models.empty()) {
    options.backend = m_models.front().card().featureBackend;
    options.resolution = m_models.front().card().gridResolution;
  }
  return options;
}

}  // namespace sagrid
