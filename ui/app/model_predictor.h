// Runs SAGrid for the GUI: the model cards in a folder (resources/models by default, loaded on
// first use) predict points and distance fields for the open object on the prediction worker.
// Objects whose category has no model get no job: they open normally and points are placed by
// hand. An unknown category is retrieved from the object's descriptor (core/annotate).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "core/annotate/object_confidence.h"

#include "ui/app/prediction_worker.h"

namespace sagrid {
class ModelSet;
}

namespace sagrid::ui {

class AnnotationDocument;

class ModelPredictor {
 public:
  explicit ModelPredictor(std::filesystem::path modelsDir);
  static std::filesystem::path defaultModelsDir();
  std::optional<PredictionJob> jobFor(const AnnotationDocument& document);
  // Drops the loaded models so the next job reads the folder again (after training).
  void reload() { m_models.reset(), m_loadFailed = false; }
  // The models folder's confidence map (confidence.json), read with the models.
  const ConfidenceCalibration& confidence() const { return m_confidence; }
  const std::filesystem::path& modelsDir() const { return m_modelsDir; }
  void setModelsDir(std::filesystem::path dir) { m_modelsDir = std::move(dir), reload(); }
  // Whether the category classifier reads the words of the mesh file's name (AnnotateOptions::
  // readFileName; Session::categoryReadsFileName: off, the shape alone).
  void setReadFileName(bool read) { m_readFileName = read; }

 private:
  std::filesystem::path m_modelsDir;
  std::shared_ptr<const ModelSet> m_models;
  bool m_loadFailed = false;
  bool m_readFileName = true;
  ConfidenceCalibration m_confidence;
};

}  // namespace sagrid::ui
