#include "ui/app/model_predictor.h"

#include <algorithm>
#include <system_error>

#include "core/annotate/annotate.h"
#include "core/annotate/model_set.h"
#include "core/annotate/suggested_points.h"
#include "core/annotate/units_record.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/common/resource_paths.h"
#include "ui/document/annotation_document.h"

namespace sagrid::ui {

namespace fs = std::filesystem;

ModelPredictor::ModelPredictor(fs::path modelsDir) : m_modelsDir(std::move(modelsDir)) {}

fs::path ModelPredictor::defaultModelsDir() { return sagrid::defaultModelsDir(); }

std::optional<PredictionJob> ModelPredictor::jobFor(const AnnotationDocument& document) {
  if (!m_models && !m_loadFailed) {
    std::error_code ec;
    if (!fs::is_directory(m_modelsDir, ec)) {
      m_loadFailed = true;
      logger()->info("no model folder {}: points are placed by hand", m_modelsDir.string());
    } else {
      try {
        m_models = std::make_shared<const ModelSet>(ModelSet::load(m_modelsDir));
        m_confidence = readConfidenceCalibration(m_modelsDir);
      } catch (const Error& e) {
        m_loadFailed = true;  // say it once, not for every object
        logger()->warn("models in {} cannot be used: {}", m_modelsDir.string(), e.what());
      }
    }
  }
  if (!m_models || document.meshPath().empty()) return std::nullopt;
  const std::string category = document.labels().object.category;
  const auto categories = m_models->categories();
  if (!category.empty() &&
      std::find(categories.begin(), categories.end(), category) == categories.end()) {
    return std::nullopt;  // a category we have no model for: by hand
  }
  AnnotateOptions options;
  options.category = category;  // empty: retrieval
  options.features = m_models->featureOptions();
  options.features.up = document.mesh().fileUp;
  options.confidence = m_confidence;
  options.readFileName = m_readFileName;
  const fs::path mesh = document.meshPath();
  const fs::path labelsDir = document.labelsPath().parent_path();
  const std::string id = document.labels().object.id;
  const Normalization normalization = document.normalization();
  return PredictionJob([models = m_models, options, mesh, labelsDir, id,
                        normalization](PredictionProgress& progress) {
    AnnotateOptions withProgress = options;
    withProgress.cancel = &progress.cancel;
    withProgress.onProgress = [&progress](float fraction, const std::string&) {
      progress.fraction = 0.95f * fraction;  // the rest: handing the fields to the document
    };
    AnnotationResult r = annotateMeshFile(mesh, id, *models, withProgress, labelsDir);
    if (progress.cancel) throw Cancelled();
    PredictionResult result;
    result.category = r.category;
    result.rejected = r.rejected;
    result.closestCategory = r.closestCategory;
    result.categoryNameWords = r.categoryNameWords;
    result.categoryByShapeAlone = r.categoryByShapeAlone;
    result.rejectedByEvidence = r.rejectedByEvidence;
    result.points = r.labels.affordances;
    result.objectConfidence = r.objectConfidence;
    result.units = recordedUnitGuess(r.labels.object);
    result.suggestedCategory = suggestedCategory(r.labels);
    for (const ModelPrediction& p : r.predictions) {
      DistanceField field;
      field.type = p.type;
      field.resolution = p.field.resolution;
      field.normalization = normalization;
      field.voxels = p.field.voxels;
      field.distances.reserve(p.field.distances.size());
      for (float d : p.field.distances) field.distances.push_back(normalization.lengthToMesh(d));
      result.fields.push_back(std::move(field));
    }
    progress.fraction = 1.0f;
    return result;
  });
}

}  // namespace sagrid::ui
