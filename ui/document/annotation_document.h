// The annotation document: one object under review — its mesh (z-up), a surface for picking,
// its labels (the affordance points, in the mesh file's coordinates), the distance fields shown
// with it, the selection, and the undo/redo history. Every change goes through execute()/undo()/
// redo() and is autosaved atomically to labels.json, so a crash or kill loses nothing.
#pragma once

#include "core/mesh/unit_guess.h"

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/labels/labels.h"
#include "core/mesh/mesh.h"
#include "ui/document/command.h"
#include "ui/document/distance_field.h"

namespace sagrid {
class SurfaceScene;
struct PartEditSurface;
}

namespace sagrid::ui {

// Whether labels say what the mesh unit is (the curator's, a declaration's or a guess's).
bool unitsKnown(const ObjectLabels& labels);

class AnnotationDocument {
 public:
  // `labelsPath` empty = no autosave (tests of commands alone, previews).
  AnnotationDocument(std::shared_ptr<const Mesh> mesh, ObjectLabels labels,
                     std::filesystem::path labelsPath, std::filesystem::path meshPath = {});
  ~AnnotationDocument();

  const Mesh& mesh() const { return *m_mesh; }
  std::shared_ptr<const Mesh> sharedMesh() const { return m_mesh; }
  const SurfaceScene& surface() const;  // built on first use
  // The mesh welded for the part edits (Grow, Shrink, the brush); built on first use.
  const PartEditSurface& partEditSurface() const;
  const ObjectLabels& labels() const { return m_labels; }
  const std::vector<AffordancePoint>& points() const { return m_labels.affordances; }
  const std::filesystem::path& labelsPath() const { return m_labelsPath; }
  const std::filesystem::path& meshPath() const { return m_meshPath; }
  std::string displayName() const;

  // Between the mesh file's frame (labels) and the z-up frame the viewport draws in.
  Eigen::Vector3f toView(const Eigen::Vector3f& filePoint) const;
  Eigen::Vector3f toFile(const Eigen::Vector3f& viewPoint) const;
  Eigen::Vector3f pointInView(int index) const {
    return toView(points()[std::size_t(index)].position);
  }
  float metersPerUnit() const { return m_metersPerUnit; }
  // Whether the labels say what the mesh unit is; if not, lengths are shown in "units", not "m".
  bool unitsKnown() const { return ui::unitsKnown(m_labels); }
  // Records annotate's guess of the units (flagged until the curator sets them, SetUnitsCommand).
  void setUnitGuess(const UnitGuess& guess);
  // Records that the points are suggestions of `category` for a rejected object
  // (core/annotate/suggested_points.h).
  void setSuggestedCategory(const std::string& category);
  const char* lengthUnit() const { return unitsKnown() ? "m" : "units"; }

  // Editing (autosaves; throws sagrid::Error if the save fails — the edit itself stays applied).
  void execute(std::unique_ptr<Command> command);
  bool undo();
  bool redo();
  bool canUndo() const { return m_history.canUndo(); }
  bool canRedo() const { return m_history.canRedo(); }
  std::string undoDescription() const { return m_history.undoDescription(); }
  std::string redoDescription() const { return m_history.redoDescription(); }
  std::size_t historySize() const { return m_history.size(); }

  // Review metadata (not part of the undo history): written to labels.json "review".
  void setReviewState(ReviewState state);
  void setCategory(const std::string& category);

  // Predicted points for an object that has none yet: the starting point of its review (not an
  // edit, not undoable); saved at once.
  void adoptPredictedPoints(std::vector<AffordancePoint> points);
  // Another starting point of the review, as one undoable step (the points of a curated object
  // of the same geometry): while it stands, the review compares to it (editedByHand); undone, or
  // dropped from the history by a later edit, the review compares to the opened points again.
  void startReviewWith(std::unique_ptr<Command> command);

  // Turns the view mesh to another file up axis and rebuilds what depends on it (surface,
  // normalization, voxels; predicted fields are dropped). Labels are the caller's: this is for
  // TurnUpAxisCommand, which also changes object.up.
  void setMeshUpAxis(UpAxis up);

  void save() const;  // atomic; no-op without a labels path or with autosave off
  // Off for previews (sagrid render): edits and predictions stay in memory.
  void setAutosave(bool enabled) { m_autosave = enabled; }

  int selected() const { return m_selected; }
  void select(int index);  // -1 = none; out-of-range indices clear the selection

  // Point edits by hand since the object opened (moves, adds, deletes, type changes).
  bool editedByHand() const;
  bool allAccepted() const;  // every point accepted/edited/added (none still "predicted")

  // Changes whenever labels or selection change; renderers compare it to re-upload only then.
  std::uint64_t revision() const { return m_revision; }
  // Changes with the labels (points, controls, category, units, review), not with the selection:
  // what is derived from the labels alone (found control parts, the turned mesh) keys on it.
  std::uint64_t labelsRevision() const { return m_labelsRevision; }

  // Distance fields shown in the viewport: predicted ones replace the fields of the labels.
  void setPredictedFields(std::vector<DistanceField> fields);
  const std::vector<DistanceField>& predictedFields() const { return m_predictedFields; }
  std::uint64_t fieldsRevision() const { return m_fieldsRevision; }
  // The occupied voxels of the object's 64^3 grid and its normalization (computed on first use).
  const std::vector<VoxelIndex>& occupiedVoxels() const;
  const Normalization& normalization() const { return m_normalization; }
  int gridResolution() const { return m_resolution; }
  // Fields of the current points, one per type present (for objects without a prediction).
  std::vector<DistanceField> labelFields() const;

 private:
  void changed();

  std::shared_ptr<const Mesh> m_mesh;
  mutable std::unique_ptr<SurfaceScene> m_surface;
  mutable std::unique_ptr<PartEditSurface> m_partEditSurface;
  ObjectLabels m_labels;
  std::filesystem::path m_labelsPath;
  std::filesystem::path m_meshPath;
  CommandStack m_history;
  std::size_t m_openedPointCount = 0;
  struct ReviewStart {
    std::size_t applied;  // the history's applied() just after the starting step
    std::size_t pointCount;
  };
  std::optional<ReviewStart> m_reviewStart;  // see startReviewWith
  bool m_removedPoint = false;
  int m_selected = -1;
  std::uint64_t m_revision = 1;
  std::uint64_t m_labelsRevision = 1;
  float m_metersPerUnit = 1.0f;
  bool m_autosave = true;

  Normalization m_normalization;
  int m_resolution = kDefaultGridResolution;
  mutable std::vector<VoxelIndex> m_occupied;
  mutable bool m_occupiedReady = false;
  std::vector<DistanceField> m_predictedFields;
  std::uint64_t m_fieldsRevision = 1;
};

}  // namespace sagrid::ui
