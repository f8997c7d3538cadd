// The category classifier with rejection: stove | sink | none from an object's descriptor (the
// feature pipeline's, the same that model cards record for retrieval). Retrieval by similarity to
// the category means alone always answers one of the known categories, so microwaves, ovens and
// cabinets got stove or sink points; this classifier has a "none" class trained on distractors.
//
// Model: multinomial logistic regression (linear softmax) over the descriptor standardized with
// the training set's mean and spread (and, by default, its squares: a quadratic boundary), trained
// full-batch with class-balanced weights and an L2 penalty (convex, deterministic, no libtorch).
// Decision: the most probable class; an object is rejected ("none") when that class is "none" or
// its probability is below `threshold`. Inputs: the descriptor, and as its file says also the
// relief of the object's top (core/grid/top_relief.h: basins, burner spots, flat lids) and the
// statistics of the mesh's parts (core/geometry/part_statistics.h: families of copies such as
// burner caps and rows of knobs), which the descriptor misses, and the words of the mesh file's
// name (core/annotate/name_evidence.h: learned from curated objects' names, multiplied into the
// shape's probabilities with the weight core/annotate/name_weight_fit.h learns). Stored as
// <models folder>/category.json (kCategoryClassifierFile) next to the model cards.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "core/annotate/name_evidence.h"
#include "core/features/descriptor_cache.h"
#include "core/points/boosted_trees.h"

namespace sagrid {

inline constexpr const char* kCategoryClassifierFile = "category.json";
inline constexpr const char* kRejectedCategory = "none";

// What the classifier reads beside the descriptor (recorded in its file).
struct CategoryInputSet {
  bool topRelief = false;       // the relief of the object's top, from its voxels
  bool partStatistics = false;  // the statistics of its mesh's parts
  bool fileName = false;        // the words of its mesh file's name
  bool operator<(const CategoryInputSet& o) const {
    return std::tie(topRelief, partStatistics, fileName) <
           std::tie(o.topRelief, o.partStatistics, o.fileName);
  }
};

struct CategoryDecision {
  std::string category;  // a known category, or kRejectedCategory
  double score = 0;      // probability of the best non-"none" class (retrieval: similarity)
  bool rejected = false;
  std::string best;      // the best non-"none" class even when rejected (what a curator may pick)
  // The words of the file's name that moved the decision beside the shape (those the classifier's
  // curated names held); empty where it reads no name.
  std::vector<std::string> nameWords;
  // The power of those words' likelihoods (name_weight_fit.h); 0 where it reads no name.
  double nameWeight = 0;
  // The category the shape alone decides at the same threshold: where it differs from category,
  // the file's name decided (a curator may want to know; a misleading name is where it errs).
  std::string shapeCategory;
  // The classifier's probability of each class as decided, and from the shape alone (the same
  // where no name moved it); empty for retrieval.
  std::map<std::string, double> probabilities, shapeProbabilities;
};

struct CategorySample {
  std::string id;
  std::string category;  // "stove", "sink", or anything else = distractor ("none")
  std::string group;     // where it came from (dataset folder, distractor kind), for reports
  std::string source;    // its source for leave-one-source-out (core/dataset/object_source.h)
  std::vector<float> descriptor;
  double weight = 1.0;  // relative weight in training (few real objects among many generated)
  std::filesystem::path mesh;  // the object's mesh (the evidence gate runs the models on it)
  std::string up;              // its labels' up axis, empty = the caller's
  std::filesystem::path featureCache;  // where its features were cached (the models' runs reuse it)
  std::vector<std::string> nameWords;  // fileNameWords(mesh)
  // Its file's name is its publisher's (a curated file: its labels hold the file's sha256 and no
  // generator record): the name evidence learns from it. Generated objects ("mesh.glb") do not.
  bool publishedName = false;
};

// The affordance-evidence gate after the classifier (core/annotate/category_evidence.h): an object
// the classifier files under a category is rejected after all when the best point that
// category's models find on it has a confidence below the category's threshold (a blender's jug
// looks like a basin, but the sink models find no tap on it). Fitted by `sagrid category
// evidence` for the models whose weights it records; a model set with other weights ignores it.
struct EvidenceGate {
  std::map<std::string, double> thresholds;      // category -> least best-point confidence
  std::map<std::string, std::string> modelShas;  // model name -> weights sha256 it was fitted with
  nlohmann::json record = nlohmann::json::object();  // how it was fitted (data, keep share, counts)
  // The models are asked only where the classifier is unsure: a category decided with at least
  // this probability stands whatever its evidence (a standalone faucet the classifier is sure of,
  // on which the sink models, trained on faucets over basins, are unsure of their points). Unset:
  // every decision is checked.
  std::optional<double> sureProbability;

  bool empty() const { return thresholds.empty(); }
  // True when `category` has no threshold or `evidence` reaches it.
  bool passes(const std::string& category, double evidence) const;
  // True when a decision with this probability is checked (below sureProbability).
  bool asks(double probability) const;
};

struct CategoryTrainingOptions {
  double l2 = 1e-2;         // penalty on the weights (standardized inputs)
  int iterations = 20000;   // full-batch gradient steps (3000 left bench val 1-2 points lower)
  double learningRate = 0.5;
  double threshold = 0.5;   // rejection threshold stored in the file
  // Also the squares of the standardized dimensions (a quadratic boundary: "far from the
  // stoves in this dimension" is not linear in it).
  bool quadratic = true;
  // What the samples' inputs hold beside the descriptor (categoryInputs); recorded in the file so
  // that classification appends the same.
  CategoryInputSet inputs;
  // With inputs.fileName: the power of the words' likelihoods, fixed; unset, it is fitted
  // (name_weight_fit.h).
  std::optional<double> nameWeight;
  // Boosted trees per class (one against the rest, on the standardized inputs without squares)
  // instead of the softmax; a class's probability is its trees' sigmoid over the classes' sum.
  bool trees = false;
  BoostingOptions boosting;
};

struct FeatureGrid;
struct Mesh;

// What the classifier reads of an object: the descriptor, followed by the top relief and then the
// part statistics where `set` asks for them.
std::vector<float> categoryInputs(const ObjectDescriptor& object, const CategoryInputSet& set);
// The same of an object's features and the mesh they came from (its top relief from the grid's
// voxels, its part statistics from the mesh: each computed only where `set` asks for it; from
// `meshParts`, connectedAndMaterialParts(mesh), where given).
std::vector<float> categoryInputs(const FeatureGrid& grid, const Mesh& mesh,
                                  const CategoryInputSet& set,
                                  const std::vector<ConnectedPart>* meshParts = nullptr);

class CategoryClassifier {
 public:
  // Throws FileError naming the file when it is unreadable or malformed, or its sha256 does not
  // match its content (a hand-edited or truncated file).
  static CategoryClassifier load(const std::filesystem::path& file);
  // Writes JSON with a sha256 over the content (atomically).
  void save(const std::filesystem::path& file) const;

  // Throws InvalidArgument when there are no samples, fewer than two classes, or descriptors of
  // different sizes.
  static CategoryClassifier train(const std::vector<CategorySample>& samples,
                                  const CategoryTrainingOptions& options);

  // Class probabilities in classes() order; throws InvalidArgument for a descriptor of the wrong
  // size. Where the classifier reads the file's name (inputSet().fileName), the shape's
  // probabilities times the likelihoods of `nameWords` (fileNameWords of the mesh), normalised.
  std::vector<double> probabilities(const std::vector<float>& descriptor,
                                    const std::vector<std::string>& nameWords = {}) const;
  CategoryDecision classify(const std::vector<float>& descriptor,
                            const std::vector<std::string>& nameWords = {}) const;
  CategoryDecision classify(const std::vector<float>& descriptor,
                            const std::vector<std::string>& nameWords, double threshold) const;
  // classify(s.descriptor, s.nameWords).
  CategoryDecision classify(const CategorySample& s) const;

  const std::vector<std::string>& classes() const { return m_classes; }
  double threshold() const { return m_threshold; }
  void setThreshold(double t) { m_threshold = t; }
  std::size_t descriptorSize() const { return m_centre.size(); }  // all inputs (categoryInputs)
  const CategoryInputSet& inputSet() const { return m_inputs; }  // categoryInputs(..., inputSet())

  // Feature setup the descriptors came from (checked against the model cards).
  std::string featureBackend, featureConfigHash;
  int gridResolution = 0;
  // Free-form record of the training run (data folders, command, counts, accuracy).
  nlohmann::json training = nlohmann::json::object();
  // Saved as "evidence" (covered by the file's sha256); empty = no gate.
  EvidenceGate evidence;

 private:
  std::vector<std::string> m_classes;  // "none" always last
  std::vector<float> m_centre, m_scale;
  std::vector<double> shapeProbabilities(const std::vector<float>& descriptor) const;
  // The decision on class probabilities `p`: the likeliest known category and its probability,
  // rejected where "none" is likeliest or that probability is below `threshold`.
  struct Verdict {
    std::string best;
    double score = 0;
    bool rejected = false;
  };
  Verdict verdict(const std::vector<double>& p, double threshold) const;
  // `shape` times the likelihoods of `nameWords` where the classifier reads names, normalised.
  std::vector<double> withNameEvidence(std::vector<double> shape,
                                       const std::vector<std::string>& nameWords) const;
  // Standardized (clamped to +-kClamp) descriptor, then its squares when m_quadratic.
  std::vector<double> inputs(const std::vector<float>& descriptor) const;
  bool m_quadratic = false;
  CategoryInputSet m_inputs;
  std::vector<std::vector<double>> m_weights;  // classes x inputs (empty with trees)
  std::vector<double> m_bias;
  std::vector<BoostedTrees> m_trees;  // one per class, or none (the softmax decides)
  NameEvidence m_names;  // counted from the training objects' published names (inputs.fileName)
  double m_threshold = 0.5;
};

// The class a labelled category trains: stove and sink as they are, everything else "none".
std::string categoryClass(const std::string& labelledCategory);

}  // namespace sagrid
