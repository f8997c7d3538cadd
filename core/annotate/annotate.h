// `sagrid annotate`: mesh -> features -> every model of the object's category -> points ->
// labels.json. The category comes from the caller or from descriptor retrieval against the model
// cards. Per model: distance field over the occupied voxels, instances (automatic count by
// default, k-means with a given count, or the paper's single argmin), each mapped to the mesh
// file's frame and projected onto the surface, with a confidence.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/annotate/model_set.h"
#include "core/annotate/object_confidence.h"
#include "core/annotate/pass_options.h"
#include "core/labels/labels.h"
#include "core/points/point_extraction.h"
#include "core/points/surface_projection.h"

namespace sagrid {

class SurfaceScene;
struct FeatureGrid;

enum class InstanceMode {
  Auto,    // local minima + non-maximum suppression, settings from the model card
  Single,  // the paper: argmin over occupied voxels
  Count,   // threshold + k-means with a known count
};

struct ModelPrediction {
  std::string modelName;
  std::string type;
  PredictedField field;
  std::vector<ExtractedPoint> points;  // normalized frame, best first
  std::vector<SurfacePoint> surface;   // projected, mesh file frame
  std::string source;                  // "<model>@<sha prefix>"
};

// The model's distance field over the occupied voxels. `symmetries` > 1 averages it over that many
// symmetric copies of the object (test-time augmentation, core/annotate/symmetry_averaging.h).
PredictedField predictField(const model::AffordanceModel& model, const FeatureGrid& features,
                            int symmetries = 1);
// Sets `prediction`'s points (normalized frame) to `points`: one at the position of a point it
// had keeps that point's surface point, the others are projected onto the surface. The learned
// point decision sets its chosen points through it.
void setPoints(ModelPrediction& prediction, std::vector<ExtractedPoint> points,
               const FeatureGrid& features, const SurfaceScene& scene, UpAxis fileUp);

// Points (instance mode) from a field predicted by `model`, projected onto the surface.
ModelPrediction predictionFromField(const model::AffordanceModel& model, PredictedField field,
                                    const FeatureGrid& features, const SurfaceScene& scene,
                                    UpAxis fileUp, InstanceMode mode, int count = 1,
                                    const ExtractionSettings* settings = nullptr);

// `settings` overrides the card's point-extraction settings when given. `symmetries` > 1 averages
// the field over that many symmetric copies of the object (test-time augmentation, see
// core/annotate/symmetry_averaging.h; 8 = all of them).
ModelPrediction predictWithModel(const model::AffordanceModel& model, const FeatureGrid& features,
                                 const SurfaceScene& scene, UpAxis fileUp, InstanceMode mode,
                                 int count = 1, const ExtractionSettings* settings = nullptr,
                                 int symmetries = 1);

// The passes after each model (symmetries, coarse-to-fine, the automatic count's passes) are the
// PassOptions this extends.
struct AnnotateOptions : PassOptions {
  std::string category;     // empty: retrieval
  // A rejected object ("none") still gets its likeliest category's points, flagged as suggestions
  // (core/annotate/suggested_points.h); off: no points, as before.
  bool suggestions = true;
  // The category classifier reads the words of the mesh file's name where its file says so
  // (core/annotate/name_evidence.h); off: the shape alone (a collection named for other things).
  bool readFileName = true;
  FeatureOptions features;  // backend must match the cards; cacheDir optional
  InstanceMode mode = InstanceMode::Auto;
  std::map<std::string, int> counts;  // type -> known instance count (InstanceMode::Count)
  // Maps the least-sure point to P(right with one key) (core/annotate/object_confidence.h);
  // unfitted = the uncalibrated map.
  ConfidenceCalibration confidence;
  // Checked before each stage (import, features, each model); when set, annotateMeshFile throws
  // Cancelled. May be null.
  const std::atomic<bool>* cancel = nullptr;
  // Called before each stage with the fraction done in [0, 1] and the stage's name ("import",
  // "features", a model name), and with 1 at the end.
  std::function<void(float fraction, const std::string& stage)> onProgress;
};

struct AnnotationResult {
  ObjectLabels labels;
  std::string category;
  double categorySimilarity = 0;  // cosine similarity to the category mean (retrieval)
  bool categoryRetrieved = false;
  // The category classifier (models folder's category.json) found no known category: category
  // "none"; with AnnotateOptions::suggestions its points are closestCategory's, flagged as
  // suggestions (predictions stays empty). closestCategory is its best guess, for a curator.
  bool rejected = false;
  std::string closestCategory;
  // The words of the mesh file's name that moved the classifier's decision (CategoryDecision).
  std::vector<std::string> categoryNameWords;
  // What the shape alone decided (CategoryDecision::shapeCategory), where the name changed it;
  // empty otherwise.
  std::string categoryByShapeAlone;
  // Rejected by the evidence gate (EvidenceGate in category_classifier.h): the classifier filed it
  // under closestCategory, but that category's models found too little of it.
  bool rejectedByEvidence = false;
  std::vector<ModelPrediction> predictions;
  double evidence = 0;  // the category's evidence (CategoryPoints::evidence)
  double objectConfidence = 0;  // P(right with one key), see AnnotateOptions::confidence
  double importSeconds = 0, featureSeconds = 0, modelSeconds = 0;
};

// `labelsDir` is where labels.json will be written (object.mesh is made relative to it).
AnnotationResult annotateMeshFile(const std::filesystem::path& meshFile, const std::string& id,
                                  const ModelSet& models, const AnnotateOptions& options,
                                  const std::filesystem::path& labelsDir);

}  // namespace sagrid
