#include "core/annotate/annotate.h"

#include <algorithm>
#include <chrono>

#include "core/annotate/category_evidence.h"
#include "core/annotate/point_passes.h"
#include "core/annotate/point_scorer.h"
#include "core/annotate/suggested_points.h"
#include "core/annotate/symmetry_averaging.h"
#include "core/annotate/units_record.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/controls/control_annotation.h"
#include "core/dataset/object_source.h"
#include "core/features/feature_grid.h"
#include "core/features/vector_channels.h"
#include "core/geometry/material_parts.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

// How the points were decided, for the curator and the record: the learned decision (what its
// scorer was trained on, the passes it switched off) or the network's count.
void recordPointDecision(ObjectLabels& labels, const PassOptions& passes) {
  auto& prediction = labels.extra["prediction"];
  if (!passes.scorer) {
    prediction["point_decision"] = "count";
    return;
  }
  prediction["point_decision"] = "learned";
  prediction["point_scorer"] = {{"trained_on", passes.scorer->trainedOn},
                                {"passes_off", passes.scorer->passesOff}};
}

// Not a stove or sink: no points; the closest category is kept for the curator. `evidence`: the
// evidence gate rejected it (its value), else the classifier did.
void recordRejection(AnnotationResult& r, std::optional<double> evidence = std::nullopt) {
  r.labels.extra["prediction"] = {{"category_score", r.categorySimilarity},
                                  {"category_retrieved", true},
                                  {"category_rejected", true},
                                  {"closest_category", r.closestCategory}};
  if (evidence) {
    r.labels.extra["prediction"]["rejected_by"] = "evidence";
    r.labels.extra["prediction"]["affordance_evidence"] = *evidence;
  }
}
// The models' points as labels: status predicted, with their confidence and model source.
void appendPredictedPoints(ObjectLabels& labels, const std::vector<ModelPrediction>& predictions) {
  for (const auto& p : predictions)
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      AffordancePoint a;
      a.type = p.type;
      a.position = p.surface[i].position;
      a.normal = p.surface[i].normal;
      a.status = AffordanceStatus::Predicted;
      a.confidence = p.points[i].confidence;
      a.source = p.source;
      labels.affordances.push_back(std::move(a));
    }
}

// The named-unit guess, or the size of curated objects like it where the folder remembers them
// and the named unit is far from it (core/annotate/size_memory.h). The decided category, rejected
// objects as "none".
UnitGuess unitGuessOf(const Mesh& mesh, const FeatureGrid& features, const std::string& category,
                      const ModelSet& models) {
  const SizeMeasures sizes = measureSizes(mesh);
  const UnitGuess guess = guessMetersPerUnit(sizes.largestExtent, category);
  const SizeMemory* memory = models.sizeMemory();
  return memory ? memory->refine(guess, sizes, features.descriptor, category) : guess;
}

}  // namespace

PredictedField predictField(const model::AffordanceModel& model, const FeatureGrid& features,
                            int symmetries) {
  PredictedField field;
  field.resolution = features.resolution;
  field.voxels = features.voxels;
  if (symmetries > 1) {
    FeatureOptions featureShape;
    featureShape.backend = model.card().featureBackend;
    featureShape.resolution = model.card().gridResolution;
    field.distances = symmetryAveragedDistances(
        model, features, vectorChannelTriples(featureChannelNames(featureShape)), symmetries);
  } else {
    field.distances = model.predictDistances(features);
  }
  return field;
}

void setPoints(ModelPrediction& prediction, std::vector<ExtractedPoint> points,
               const FeatureGrid& features, const SurfaceScene& scene, UpAxis fileUp) {
  std::vector<SurfacePoint> surface;
  for (const auto& point : points) {
    std::size_t kept = 0;
    while (kept < prediction.points.size() && prediction.points[kept].position != point.position)
      ++kept;
    surface.push_back(
        kept < prediction.points.size()
            ? prediction.surface[kept]
            : projectToSurface(point.position, features.normalization, scene, fileUp));
  }
  prediction.points = std::move(points);
  prediction.surface = std::move(surface);
}

ModelPrediction predictionFromField(const model::AffordanceModel& model, PredictedField field,
                                    const FeatureGrid& features, const SurfaceScene& scene,
                                    UpAxis fileUp, InstanceMode mode, int count,
                                    const ExtractionSettings* settings) {
  ModelPrediction p;
  const auto& card = model.card();
  const ExtractionSettings& extraction = settings ? *settings : card.extraction;
  p.modelName = card.name;
  p.type = card.type;
  p.source = card.sourceTag();
  p.field = std::move(field);
  std::vector<ExtractedPoint> points;
  switch (mode) {
    case InstanceMode::Single:
      points = {argminPoint(p.field, extraction)};
      break;
    case InstanceMode::Count:
      points = kMeansPoints(p.field, count, extraction);
      break;
    case InstanceMode::Auto:
      points = autoCountPoints(p.field, extraction);
      break;
  }
  setPoints(p, std::move(points), features, scene, fileUp);
  return p;
}

ModelPrediction predictWithModel(const model::AffordanceModel& model, const FeatureGrid& features,
                                 const SurfaceScene& scene, UpAxis fileUp, InstanceMode mode,
                                 int count, const ExtractionSettings* settings, int symmetries) {
  return predictionFromField(model, predictField(model, features, symmetries), features, scene,
                             fileUp, mode, count, settings);
}

AnnotationResult annotateMeshFile(const fs::path& meshFile, const std::string& id,
                                  const ModelSet& models, const AnnotateOptions& options,
                                  const fs::path& labelsDir) {
  AnnotationResult r;
  // Import and features take most of the time (about 0.1 and 0.6 of it); models share the rest.
  auto stage = [&options](float fraction, const std::string& name) {
    if (options.cancel && options.cancel->load()) throw Cancelled();
    if (options.onProgress) options.onProgress(fraction, name);
  };
  stage(0.0f, "import");
  auto t = Clock::now();
  // Without --up the up axis is the one a provenance.json beside the mesh declares, else detected
  // from the geometry (formats that do not fix it); the features are then computed in that frame.
  const std::optional<UpAxis> up =
      options.features.up ? options.features.up : declaredUpAxis(meshFile);
  const Mesh mesh = importMesh(meshFile, ImportOptions(up, /*detect=*/true));
  r.importSeconds = secondsSince(t);
  stage(0.1f, "features");
  t = Clock::now();
  FeatureOptions featureOptions = options.features;
  featureOptions.up = mesh.fileUp;
  const FeatureGrid features = featureOptions.cacheDir.empty()
                                   ? computeFeatures(mesh, featureOptions)
                                   : extractFeatures(meshFile, featureOptions);
  const SurfaceScene scene(mesh);
  r.featureSeconds = secondsSince(t);

  // The classifier's (or retrieval's) decision when the caller names no category; its evidence
  // gate is applied below, once the category's models have run.
  std::optional<CategoryDecision> decided;
  // The mesh's parts, found once where the classifier reads them; the learned point decision
  // seeds its candidates from the same.
  std::optional<std::vector<ConnectedPart>> meshParts;
  if (options.category.empty() && models.categoryInputSet().partStatistics)
    meshParts = connectedAndMaterialParts(mesh);
  const ObjectForPasses object{mesh, features, scene, featureOptions,
                               meshParts ? &*meshParts : nullptr};
  if (options.category.empty()) {
    // The classifier with rejection when the models folder has one (reading the mesh's parts
    // where its file says so), else retrieval.
    const CategoryDecision& decision = decided.emplace(models.decideCategory(
        features, mesh, object.meshParts, options.readFileName ? meshFile : fs::path()));
    r.category = decision.category;
    r.categorySimilarity = decision.score;
    r.categoryRetrieved = true;
    r.rejected = decision.rejected;
    r.closestCategory = decision.best;
    r.categoryNameWords = decision.nameWords;
    if (decision.shapeCategory != decision.category)
      r.categoryByShapeAlone = decision.shapeCategory;
  } else {
    r.category = options.category;
    r.categorySimilarity = models.categorySimilarity(features.descriptor, options.category);
  }

  t = Clock::now();
  const PassOptions passes = withLearnedDecision(options, models);
  r.labels.object.id = id;
  r.labels.object.mesh =
      fs::proximate(fs::absolute(meshFile), fs::absolute(labelsDir)).generic_string();
  r.labels.object.sha256 = mesh.sha256;
  r.labels.object.category = r.category;
  r.labels.object.up = toString(mesh.fileUp);
  if (mesh.fileUpDetected) r.labels.object.upConfidence = mesh.fileUpConfidence;
  if (const auto declared = declaredMetersPerUnit(meshFile))
    recordDeclaredUnits(r.labels.object, *declared, "provenance.json");
  else
    recordUnitGuess(r.labels.object, unitGuessOf(mesh, features, r.category, models));
  // The model stage's time and the final progress report, on every way out.
  auto finish = [&] {
    // What of the file's name moved the category (the classifier's known words), for a curator.
    if (!r.categoryNameWords.empty())
      r.labels.extra["prediction"]["category_name_words"] = r.categoryNameWords;
    if (!r.categoryByShapeAlone.empty())
      r.labels.extra["prediction"]["category_by_shape_alone"] = r.categoryByShapeAlone;
    r.modelSeconds = secondsSince(t);
    if (options.onProgress) options.onProgress(1.0f, "done");
  };
  if (r.rejected) {
    recordRejection(r);
    const auto known = models.categories();
    if (options.suggestions && std::find(known.begin(), known.end(), r.closestCategory) != known.end()) {
      // No hard gate: the likeliest category's points, as suggestions.
      const auto closestModels = models.forCategory(r.closestCategory);
      const CategoryPoints suggested =
          predictCategoryPoints(closestModels, object, passes,
                                options.mode, options.counts, [](std::size_t) {});
      appendPredictedPoints(r.labels, suggested.predictions);
      markSuggestions(r.labels, r.closestCategory);
      recordPointDecision(r.labels, passes);
    }
    finish();
    return r;
  }
  const auto categoryModels = models.forCategory(r.category);
  CategoryPoints points = predictCategoryPoints(
      categoryModels, object, passes, options.mode,
      options.counts, [&](std::size_t m) {
        stage(0.7f + 0.3f * static_cast<float>(m) / static_cast<float>(categoryModels.size()),
              categoryModels[m]->card().name);
      });
  r.predictions = std::move(points.predictions);
  appendPredictedPoints(r.labels, r.predictions);
  const double evidence = r.evidence = points.evidence;
  const auto* classifier = models.categoryClassifier();
  if (decided && classifier &&
      applyEvidenceGate(*decided, classifier->evidence, [evidence](const std::string&) {
        return evidence;
      }).rejected) {
    // The classifier's category, but its models find nothing of it here: rejected after all.
    r.rejected = r.rejectedByEvidence = true;
    r.closestCategory = r.category;
    r.category = r.labels.object.category = kRejectedCategory;
    if (options.suggestions) markSuggestions(r.labels, r.closestCategory);
    else r.labels.affordances.clear();
    r.predictions.clear();
    recordRejection(r, evidence);
    if (options.suggestions) recordPointDecision(r.labels, passes);
    finish();
    return r;
  }
  annotateControls(r.labels, mesh, scene);
  r.objectConfidence = options.confidence.probability(leastSurePointDistance(r.predictions));
  r.labels.extra["prediction"] = {{"category_similarity", r.categorySimilarity},
                                  {"category_retrieved", r.categoryRetrieved},
                                  {"object_confidence", r.objectConfidence},
                                  {"object_confidence_calibrated", options.confidence.fitted},
                                  {"symmetries", options.symmetries}};
  if (r.categoryRetrieved && classifier && !classifier->evidence.empty())
    r.labels.extra["prediction"]["affordance_evidence"] = evidence;
  recordPointDecision(r.labels, passes);
  finish();
  return r;
}

}  // namespace sagrid
