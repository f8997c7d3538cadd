#include "ui/document/annotation_document.h"

#include <map>
#include <utility>

#include "core/annotate/suggested_points.h"
#include "core/annotate/units_record.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/controls/control_part_edit.h"
#include "core/geometry/surface_scene.h"
#include "core/grid/voxelize.h"
#include "ui/document/point_commands.h"

namespace sagrid::ui {

AnnotationDocument::AnnotationDocument(std::shared_ptr<const Mesh> mesh, ObjectLabels labels,
                                       std::filesystem::path labelsPath,
                                       std::filesystem::path meshPath)
    : m_mesh(std::move(mesh)),
      m_labels(std::move(labels)),
      m_labelsPath(std::move(labelsPath)),
      m_meshPath(std::move(meshPath)) {
  m_openedPointCount = m_labels.affordances.size();
  m_metersPerUnit = static_cast<float>(sagrid::metersPerUnit(m_labels));
  m_normalization = Normalization::fromMesh(*m_mesh);
}

AnnotationDocument::~AnnotationDocument() = default;

const SurfaceScene& AnnotationDocument::surface() const {
  if (!m_surface) m_surface = std::make_unique<SurfaceScene>(*m_mesh);
  return *m_surface;
}

const PartEditSurface& AnnotationDocument::partEditSurface() const {
  if (!m_partEditSurface) m_partEditSurface = std::make_unique<PartEditSurface>(*m_mesh);
  return *m_partEditSurface;
}

std::string AnnotationDocument::displayName() const {
  if (!m_labels.object.id.empty()) return m_labels.object.id;
  if (!m_meshPath.empty())
    return m_meshPath.parent_path().filename().string() + "/" + m_meshPath.filename().string();
  return "untitled";
}

Eigen::Vector3f AnnotationDocument::toView(const Eigen::Vector3f& filePoint) const {
  return fileToZUp(filePoint, m_mesh->fileUp);
}

Eigen::Vector3f AnnotationDocument::toFile(const Eigen::Vector3f& viewPoint) const {
  return zUpToFile(viewPoint, m_mesh->fileUp);
}

bool unitsKnown(const ObjectLabels& labels) {
  const auto& object = labels.object.extra;
  const bool inObject = object.is_object() && (object.contains("meters_per_unit") || object.contains("units") ||
                                                object.contains(kUnitGuessField));
  const bool topLevel = labels.extra.is_object() && labels.extra.contains("units");  // real-dev form
  return inObject || topLevel;
}

void AnnotationDocument::execute(std::unique_ptr<Command> command) {
  const bool removes = dynamic_cast<DeletePointCommand*>(command.get()) != nullptr;
  // A new step drops the redo branch, and with it a review start that was undone.
  if (m_reviewStart && m_history.applied() < m_reviewStart->applied) m_reviewStart.reset();
  const std::string what = command->description();
  const Command* applied = command.get();
  m_history.execute(std::move(command), m_labels);
  if (applied->selectionAfterApply() >= 0) m_selected = applied->selectionAfterApply();
  if (removes) m_removedPoint = true, m_selected = -1;
  logger()->info("{}: {}", displayName(), what);
  changed();
}

bool AnnotationDocument::undo() {
  const Command* command = m_history.undo(m_labels);
  if (!command) return false;
  m_selected = command->selectionAfterRevert() >= 0 ? command->selectionAfterRevert() : -1;
  logger()->info("{}: undo {}", displayName(), command->description());
  changed();
  return true;
}

bool AnnotationDocument::redo() {
  const Command* command = m_history.redo(m_labels);
  if (!command) return false;
  m_selected = command->selectionAfterApply();
  logger()->info("{}: redo {}", displayName(), command->description());
  changed();
  return true;
}

void AnnotationDocument::changed() {
  if (m_selected >= static_cast<int>(m_labels.affordances.size())) m_selected = -1;
  m_metersPerUnit = static_cast<float>(sagrid::metersPerUnit(m_labels));  // a units edit
  ++m_revision;
  ++m_labelsRevision;
  save();
}

void AnnotationDocument::setUnitGuess(const UnitGuess& guess) {
  recordUnitGuess(m_labels.object, guess);
  changed();
}

void AnnotationDocument::setSuggestedCategory(const std::string& category) {
  m_labels.object.extra[kSuggestedCategoryField] = category;
  changed();
}

void AnnotationDocument::setReviewState(ReviewState state) {
  m_labels.reviewState = state;
  m_labels.reviewUpdated = currentUtcTimestamp();
  ++m_revision;
  ++m_labelsRevision;
  save();
}

void AnnotationDocument::setMeshUpAxis(UpAxis up) {
  if (up == m_mesh->fileUp) return;
  auto turned = std::make_shared<Mesh>(*m_mesh);
  const UpAxis from = m_mesh->fileUp;
  for (auto& p : turned->positions) p = fileToZUp(zUpToFile(p, from), up);
  for (auto& n : turned->normals) n = fileToZUp(zUpToFile(n, from), up);
  turned->fileUp = up;
  turned->fileUpDetected = false;
  turned->fileUpConfidence = 1.0f;
  m_mesh = std::move(turned);  // a new identity: renderers upload it again
  m_surface.reset();
  m_partEditSurface.reset();
  m_normalization = Normalization::fromMesh(*m_mesh);
  m_occupied.clear();
  m_occupiedReady = false;
  m_predictedFields.clear();
  ++m_fieldsRevision;
}

void AnnotationDocument::setCategory(const std::string& category) {
  m_labels.object.category = category;
  ++m_revision;
  ++m_labelsRevision;
  save();
}

void AnnotationDocument::adoptPredictedPoints(std::vector<AffordancePoint> points) {
  m_labels.affordances = std::move(points);
  m_openedPointCount = m_labels.affordances.size();
  m_removedPoint = false;
  m_history = CommandStack();
  m_reviewStart.reset();
  m_selected = -1;
  changed();
}

void AnnotationDocument::startReviewWith(std::unique_ptr<Command> command) {
  const std::size_t before = m_history.applied();
  auto markStart = [&] {
    if (m_history.applied() > before)
      m_reviewStart = ReviewStart{m_history.applied(), m_labels.affordances.size()};
  };
  try {
    execute(std::move(command));
  } catch (const Error&) {
    markStart();  // applied; only its autosave failed
    throw;
  }
  markStart();
}

void AnnotationDocument::save() const {
  if (m_labelsPath.empty() || !m_autosave) return;
  writeLabels(m_labelsPath, m_labels);
}

void AnnotationDocument::select(int index) {
  const int next =
      (index >= 0 && index < static_cast<int>(m_labels.affordances.size())) ? index : -1;
  if (next != m_selected) {
    m_selected = next;
    ++m_revision;
  }
}

bool AnnotationDocument::editedByHand() const {
  const bool fromStart = m_reviewStart && m_history.applied() >= m_reviewStart->applied;
  const std::size_t startCount = fromStart ? m_reviewStart->pointCount : m_openedPointCount;
  if (m_removedPoint || m_labels.affordances.size() != startCount) return true;
  for (const auto& p : m_labels.affordances) {
    if (p.status == AffordanceStatus::Edited || p.status == AffordanceStatus::Added) return true;
  }
  return false;
}

bool AnnotationDocument::allAccepted() const {
  for (const auto& p : m_labels.affordances) {
    if (p.status == AffordanceStatus::Predicted) return false;
  }
  return true;
}

void AnnotationDocument::setPredictedFields(std::vector<DistanceField> fields) {
  m_predictedFields = std::move(fields);
  ++m_fieldsRevision;
}

const std::vector<VoxelIndex>& AnnotationDocument::occupiedVoxels() const {
  if (!m_occupiedReady) {
    m_occupied = voxelize(normalizedCopy(*m_mesh, m_normalization), m_resolution).occupiedVoxels();
    m_occupiedReady = true;
  }
  return m_occupied;
}

std::vector<DistanceField> AnnotationDocument::labelFields() const {
  std::map<std::string, std::vector<Eigen::Vector3f>> byType;
  for (const auto& p : m_labels.affordances) byType[p.type].push_back(toView(p.position));
  std::vector<DistanceField> fields;
  for (const auto& [type, points] : byType) {
    fields.push_back(
        distanceFieldFromPoints(type, occupiedVoxels(), m_resolution, m_normalization, points));
  }
  return fields;
}

}  // namespace sagrid::ui
