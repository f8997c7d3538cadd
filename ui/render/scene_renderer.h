// Draws one AnnotationDocument's scene — ground grid, mesh, distance field voxels, point markers —
// into the current viewport, re-uploading GPU data only when the document changes (revision
// counters), never per frame.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "ui/render/camera.h"
#include "ui/render/field_renderer.h"
#include "ui/render/grid_renderer.h"
#include "ui/render/marker_renderer.h"
#include "ui/render/mesh_renderer.h"
#include "ui/render/view_settings.h"

namespace sagrid::ui {

class AnnotationDocument;

// A point being dragged: drawn at `position` (z-up) until the drag ends and becomes a command.
struct DragPreview {
  int index = -1;
  Eigen::Vector3f position = Eigen::Vector3f::Zero();
};

class SceneRenderer {
 public:
  SceneRenderer();
  // Brings GPU data up to date with `document` (nullptr = empty scene). Cheap when unchanged.
  void sync(const AnnotationDocument* document, const std::optional<DragPreview>& drag,
            const ViewSettings& settings);
  void draw(const Camera& camera, const ViewSettings& settings) const;

  const MeshRenderer& mesh() const { return m_mesh; }
  const FieldRenderer& field() const { return m_field; }
  const std::vector<DistanceField>& shownFields() const { return m_shownFields; }
  bool showingPredictedFields() const { return m_predictedShown; }

 private:
  MeshRenderer m_mesh;
  GridRenderer m_grid;
  FieldRenderer m_field;
  MarkerRenderer m_markers;
  const AnnotationDocument* m_document = nullptr;
  // Held, not only compared: a mesh freed while its address is remembered can be replaced by the
  // next object's mesh at the same address (and its document at the old document's), and the
  // next object would be drawn with the previous one's triangles.
  std::shared_ptr<const Mesh> m_shownMesh;
  std::uint64_t m_revision = 0, m_fieldsRevision = 0;
  float m_turn = 0.0f;  // the angle the uploaded mesh's controls are turned by
  std::uint64_t m_turnedLabelsRevision = 0;  // the labels it was turned for
  std::optional<DragPreview> m_drag;
  float m_markerPixels = 0;
  std::uint32_t m_typeMask = ~0u;
  std::vector<MarkerInstance> m_markerInstances;
  std::vector<DistanceField> m_shownFields;
  bool m_predictedShown = false;
};

}  // namespace sagrid::ui
