#include "core/annotate/model_set.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/common/error.h"
#include "core/common/joined.h"
#include "core/common/log.h"

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
  ModelSet set(std::move(models));
  // Old model folders have no classifier and keep retrieval.
  const auto classifierFile = directory / kCategoryClassifierFile;
  if (std::filesystem::exists(classifierFile))
    set.setCategoryClassifier(CategoryClassifier::load(classifierFile), classifierFile);
  if (auto scorer = readPointScorer(directory))
    set.setPointScorer(std::move(*scorer), directory / kPointScorerFile);
  if (auto memory = readSizeMemory(directory))
    set.setSizeMemory(std::move(*memory), directory / kSizeMemoryFile);
  return set;
}

std::map<std::string, std::string> ModelSet::weightsByModel() const {
  std::map<std::string, std::string> out;
  for (const auto& m : m_models) out[m.card().name] = m.card().weightsIdentity();
  return out;
}

void ModelSet::setPointScorer(PointScorer scorer, const std::filesystem::path& file) {
  const std::map<std::string, std::string> cardWeights = weightsByModel();
  for (const auto& [name, decision] : scorer.byModel)
    if (!cardWeights.count(name))
      throw ModelError(file.string() + ": the point scorer decides for model " + name +
                       ", which this folder has no card of; train it again with `sagrid scorer "
                       "train --models` this folder");
  for (const auto& stale : decisionsOfOtherWeights(scorer, cardWeights))
    logger()->warn(
        "{}: the point decision of {} learned from the candidates of other weights ({}) than "
        "the card's ({}); it still decides, but may no longer fit: retrain it with `sagrid "
        "scorer update --models {} --data CURATED --out DIR` (or the Train panel)",
        file.string(), stale.model, stale.learnedFrom.substr(0, 8), stale.card.substr(0, 8),
        file.parent_path().string());
  m_scorer = std::move(scorer);
}

void ModelSet::setCategoryClassifier(CategoryClassifier classifier,
                                     const std::filesystem::path& file) {
  if (!m_models.empty()) {
    const auto& card = m_models.front().card();
    if (classifier.featureBackend != card.featureBackend ||
        (!classifier.featureConfigHash.empty() &&
         classifier.featureConfigHash != card.featureConfigHash) ||
        (classifier.gridResolution != 0 && classifier.gridResolution != card.gridResolution))
      throw ModelError(file.string() + ": the category classifier was trained on other features (" +
                       classifier.featureBackend + ") than the model cards (" +
                       card.featureBackend + "); retrain it with `sagrid category train`");
  }
  const auto known = categories();
  for (const auto& c : classifier.classes())
    if (c != kRejectedCategory && std::find(known.begin(), known.end(), c) == known.end())
      throw ModelError(file.string() + ": the category classifier knows \"" + c +
                       "\" but no model card has that category");
  // The evidence gate's thresholds are confidences of these very weights: with retrained models
  // it would reject at the wrong level, so it goes (until `sagrid category evidence` refits it).
  for (const auto& [name, sha] : classifier.evidence.modelShas) {
    const auto it = std::find_if(m_models.begin(), m_models.end(),
                                 [&name = name](const auto& m) { return m.card().name == name; });
    if (it == m_models.end() || it->card().weightsIdentity() != sha) {
      logger()->warn(
          "{}: its evidence gate was fitted for other weights of {}; the gate is off "
          "until `sagrid category evidence` refits it",
          file.string(), name);
      classifier.evidence = {};
      break;
    }
  }
  m_classifier = std::move(classifier);
}

CategoryDecision ModelSet::decideCategory(const FeatureGrid& features, const Mesh& mesh,
                                          const std::vector<ConnectedPart>* meshParts,
                                          const std::filesystem::path& meshFile) const {
  if (m_classifier)
    return m_classifier->classify(
        categoryInputs(features, mesh, m_classifier->inputSet(), meshParts),
        fileNameWords(meshFile));
  return decideCategory(features.descriptor);
}

CategoryDecision ModelSet::decideCategory(const ObjectDescriptor& object,
                                          const std::filesystem::path& meshFile) const {
  if (!m_classifier) return decideCategory(object.descriptor);
  if (m_classifier->inputSet().partStatistics && !object.hasPartStatistics)
    throw InvalidArgument(
        "the category classifier reads the mesh's parts: decide from a descriptor entry that "
        "holds them");
  return m_classifier->classify(categoryInputs(object, m_classifier->inputSet()),
                                fileNameWords(meshFile));
}

CategoryDecision ModelSet::decideCategory(const std::vector<float>& descriptor) const {
  const CategoryInputSet set = categoryInputSet();
  if (set.topRelief || set.partStatistics)
    throw InvalidArgument(
        "the category classifier reads the top relief of the voxels or the mesh's parts too: "
        "decide from the object's features and mesh, not its descriptor alone");
  if (m_classifier) return m_classifier->classify(descriptor);
  const auto ranked = rankCategories(descriptor);
  if (ranked.empty()) throw ModelError("no models to choose a category from");
  CategoryDecision d;
  d.category = d.best = ranked.front().category;
  d.score = ranked.front().similarity;
  return d;
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
  if (categories().size() < 2) return;
  try {
    m_retrieval = retrievalSpace();
  } catch (const ModelError&) {
    // Cards without retrieval statistics still annotate with a given category.
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
    throw InvalidArgument("no model for category \"" + category +
                          "\" (models exist for: " + joined(categories()) + ")");
  }
  return out;
}

namespace {

// Mean over the category's cards of one recorded vector (the cards of a category see nearly the
// same objects); empty when no card records it.
std::vector<float> meanOverCards(const std::vector<const model::AffordanceModel*>& models,
                                 std::vector<float> model::ModelCard::*field) {
  std::vector<double> sum;
  int count = 0;
  for (const auto* m : models) {
    const auto& d = m->card().*field;
    if (d.empty()) continue;
    if (sum.empty()) sum.assign(d.size(), 0.0);
    if (d.size() != sum.size()) continue;
    for (std::size_t i = 0; i < d.size(); ++i) sum[i] += d[i];
    ++count;
  }
  std::vector<float> mean;
  for (double v : sum) mean.push_back(static_cast<float>(v / count));
  return mean;
}

std::vector<float> standardized(const std::vector<float>& v, const std::vector<float>& centre,
                                const std::vector<float>& scale) {
  std::vector<float> out(v.size(), 0.0f);
  for (std::size_t i = 0; i < v.size() && i < centre.size() && i < scale.size(); ++i)
    out[i] = (v[i] - centre[i]) / scale[i];
  return out;
}

}  // namespace

std::vector<float> ModelSet::categoryMean(const std::string& category) const {
  auto mean = meanOverCards(forCategory(category), &model::ModelCard::descriptorMean);
  if (mean.empty())
    throw ModelError("the " + category + " model cards record no descriptor mean for retrieval");
  return mean;
}

std::vector<float> ModelSet::categoryStd(const std::string& category) const {
  return meanOverCards(forCategory(category), &model::ModelCard::descriptorStd);
}

ModelSet::RetrievalSpace ModelSet::retrievalSpace() const {
  RetrievalSpace space;
  const auto names = categories();
  std::vector<std::vector<float>> means, stds;
  for (const auto& c : names) {
    means.push_back(categoryMean(c));
    stds.push_back(categoryStd(c));
  }
  const std::size_t size = means.front().size();
  for (const auto& m : means)
    if (m.size() != size)
      throw ModelError("model cards record descriptors of different sizes; retrain them together");
  space.centre.assign(size, 0.0f);
  space.scale.assign(size, 0.0f);
  for (std::size_t i = 0; i < size; ++i) {
    double centre = 0, variance = 0;
    int withStd = 0;
    for (std::size_t c = 0; c < means.size(); ++c) {
      centre += means[c][i];
      if (stds[c].size() == size) variance += stds[c][i] * stds[c][i], ++withStd;
    }
    space.centre[i] = static_cast<float>(centre / means.size());
    // Old cards without a spread: unit scale (centring alone).
    const double pooled = withStd > 0 ? std::sqrt(variance / withStd) : 1.0;
    space.scale[i] = static_cast<float>(std::max(pooled, 1e-3));
  }
  return space;
}

double ModelSet::categorySimilarity(const std::vector<float>& descriptor,
                                    const std::string& category) const {
  const auto mean = categoryMean(category);
  if (categories().size() < 2) return cosineSimilarity(descriptor, mean);
  const RetrievalSpace space = m_retrieval ? *m_retrieval : retrievalSpace();
  return cosineSimilarity(standardized(descriptor, space.centre, space.scale),
                          standardized(mean, space.centre, space.scale));
}

std::vector<CategoryScore> ModelSet::rankCategories(const std::vector<float>& descriptor) const {
  std::vector<CategoryScore> scores;
  for (const auto& c : categories()) scores.push_back({c, categorySimilarity(descriptor, c)});
  std::stable_sort(
      scores.begin(), scores.end(),
      [](const CategoryScore& a, const CategoryScore& b) { return a.similarity > b.similarity; });
  return scores;
}

void ModelSet::setSizeMemory(SizeMemory memory, const std::filesystem::path& file) {
  if (!m_models.empty() && memory.featureConfigHash() != featureConfigHash())
    throw ModelError(file.string() + ": its descriptors were computed with other features (" +
                     memory.featureConfigHash() + ") than the models' (" + featureConfigHash() +
                     "): build it again (sagrid units memory)");
  m_sizeMemory = std::move(memory);
}

std::string ModelSet::featureConfigHash() const {
  return m_models.empty() ? sagrid::featureConfigHash(featureOptions())
                          : m_models.front().card().featureConfigHash;
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
