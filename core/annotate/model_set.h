// The models `annotate`, `filter` and `eval` use: every model card in a folder (default
// resources/models), loaded with its weights, grouped by category, with category retrieval by
// cosine similarity of an object's descriptor to the category means recorded at training
// (paper, III-D: filtering a collection in DINOv2 feature space). With two or more categories
// the similarity is taken after centring on the mean of the category means and dividing each
// dimension by the categories' pooled spread, so that large, uninformative dimensions (shared
// by every category) do not decide it; with one category it is the plain cosine.
// When the folder holds a category classifier (category.json, category_classifier.h) it decides
// the category instead, and may answer "none" (not a stove or sink); without it, retrieval.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/annotate/category_classifier.h"
#include "core/annotate/point_scorer.h"
#include "core/annotate/size_memory.h"
#include "core/features/feature_pipeline.h"
#include "core/model/affordance_model.h"

namespace sagrid {

double cosineSimilarity(const std::vector<float>& a, const std::vector<float>& b);

struct CategoryScore {
  std::string category;
  double similarity = 0;
};

class ModelSet {
 public:
  // Throws FileError / ModelError (no cards, unreadable weights, cards needing different features).
  static ModelSet load(const std::filesystem::path& directory);
  explicit ModelSet(std::vector<model::AffordanceModel> models);

  std::vector<std::string> categories() const;
  // Models of a category in card-name order; throws InvalidArgument when there are none.
  std::vector<const model::AffordanceModel*> forCategory(const std::string& category) const;
  const std::vector<model::AffordanceModel>& models() const { return m_models; }
  // Model name -> its card's weights identity (ModelCard::weightsIdentity).
  std::map<std::string, std::string> weightsByModel() const;

  // Categories ranked by similarity of `descriptor` to their training means, best first.
  std::vector<CategoryScore> rankCategories(const std::vector<float>& descriptor) const;
  // Similarity in [-1, 1] of `descriptor` to one category; throws when the category is unknown.
  double categorySimilarity(const std::vector<float>& descriptor,
                            const std::string& category) const;
  std::vector<float> categoryMean(const std::string& category) const;  // throws when unknown

  // The category of an object: the classifier's decision (possibly rejected, category "none")
  // when the folder has one, else the best retrieved category (never rejected).
  // `meshParts`: connectedAndMaterialParts(mesh) where found already (else found here when the
  // classifier reads them). `meshFile`: the file the mesh was read from, whose name's words the
  // classifier reads where its file says so (empty: the shape alone).
  CategoryDecision decideCategory(const FeatureGrid& features, const Mesh& mesh,
                                  const std::vector<ConnectedPart>* meshParts = nullptr,
                                  const std::filesystem::path& meshFile = {}) const;
  // The same from what a descriptor cache entry holds (`sagrid filter`): it must hold what the
  // classifier reads (categoryInputSet()).
  CategoryDecision decideCategory(const ObjectDescriptor& object,
                                  const std::filesystem::path& meshFile = {}) const;
  // The same from the descriptor alone; throws InvalidArgument when the classifier also reads the
  // top relief or the parts (categoryInputSet()).
  CategoryDecision decideCategory(const std::vector<float>& descriptor) const;
  // What the classifier reads beside the descriptor (nothing without one).
  CategoryInputSet categoryInputSet() const {
    return m_classifier ? m_classifier->inputSet() : CategoryInputSet{};
  }
  const CategoryClassifier* categoryClassifier() const {
    return m_classifier ? &*m_classifier : nullptr;
  }
  // Throws ModelError naming `file` when the classifier needs other features than the cards or
  // knows a category no card has.
  void setCategoryClassifier(CategoryClassifier classifier, const std::filesystem::path& file);

  // The learned point decision of the folder (point_scorer.json); nullptr when it has none.
  const PointScorer* pointScorer() const { return m_scorer ? &*m_scorer : nullptr; }
  // Throws ModelError naming `file` when the scorer decides for a model the folder has no card of.
  void setPointScorer(PointScorer scorer, const std::filesystem::path& file);

  // Feature options matching the cards (backend, grid size); the cache folder is the caller's.
  FeatureOptions featureOptions() const;
  // The cards' feature configuration hash (that of featureOptions() for a folder without cards):
  // what files of descriptors made for these models record.
  std::string featureConfigHash() const;

  // The sizes of curated objects the units guess recalls (units_memory.json); nullptr without.
  const SizeMemory* sizeMemory() const { return m_sizeMemory ? &*m_sizeMemory : nullptr; }
  // Throws ModelError naming `file` when the memory's descriptors come from other features than
  // the cards'.
  void setSizeMemory(SizeMemory memory, const std::filesystem::path& file);

 private:
  // Centre and per-dimension scale of the retrieval space (see the file comment).
  struct RetrievalSpace {
    std::vector<float> centre, scale;
  };
  RetrievalSpace retrievalSpace() const;
  std::vector<float> categoryStd(const std::string& category) const;  // empty when not recorded

  std::vector<model::AffordanceModel> m_models;
  // Computed once when the cards allow it (every category records a mean of one size); otherwise
  // retrievalSpace() is called at use and throws its clear error there.
  std::optional<RetrievalSpace> m_retrieval;
  std::optional<CategoryClassifier> m_classifier;
  std::optional<PointScorer> m_scorer;
  std::optional<SizeMemory> m_sizeMemory;
};

}  // namespace sagrid
