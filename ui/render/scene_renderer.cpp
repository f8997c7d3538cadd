#include "ui/render/scene_renderer.h"

#include "core/mesh/mesh.h"
#include "ui/document/annotation_document.h"
#include "ui/document/control_view.h"
#include "ui/gl/gl.h"
#include "ui/render/type_colors.h"

namespace sagrid::ui {

SceneRenderer::SceneRenderer() = default;

void SceneRenderer::sync(const AnnotationDocument* document, const std::optional<DragPreview>& drag,
                         const ViewSettings& settings) {
  if (!document) {
    if (m_document) {
      m_document = nullptr;
      m_shownMesh.reset();
      m_mesh = MeshRenderer();
      m_markerInstances.clear();
      m_markers.upload(m_markerInstances);
      m_shownFields.clear();
      m_field.setFields(m_shownFields, ~0u);
    }
    return;
  }
  const bool newDocument = document != m_document || document->sharedMesh() != m_shownMesh;
  if (newDocument) {
    m_document = document;
    m_shownMesh = document->sharedMesh();
    m_mesh.upload(document->mesh());
    m_grid.build(document->mesh().bounds());
    m_revision = 0;
    m_fieldsRevision = 0;
    m_turn = 0.0f;
  }
  const bool pointsChanged = document->revision() != m_revision;
  // The controls turned (View > Controls turned): uploaded again when the angle or the labels
  // change, not per frame or per selection.
  if (settings.controlTurn != m_turn ||
      (m_turn != 0.0f && document->labelsRevision() != m_turnedLabelsRevision)) {
    m_turn = settings.controlTurn;
    m_turnedLabelsRevision = document->labelsRevision();
    m_mesh.upload(m_turn == 0.0f ? document->mesh() : meshWithControlsTurned(*document, m_turn));
  }
  const bool fieldsChanged = document->fieldsRevision() != m_fieldsRevision;
  // Predicted fields win; without them the fields follow the labels (recomputed per edit).
  if (fieldsChanged || (pointsChanged && document->predictedFields().empty())) {
    m_predictedShown = !document->predictedFields().empty();
    m_shownFields = m_predictedShown ? document->predictedFields() : document->labelFields();
    m_field.setFields(m_shownFields, settings.field.typeMask);
    m_fieldsRevision = document->fieldsRevision();
    m_typeMask = settings.field.typeMask;
  } else if (settings.field.typeMask != m_typeMask) {
    m_field.setFields(m_shownFields, settings.field.typeMask);
    m_typeMask = settings.field.typeMask;
  }
  m_field.prepare(settings.field);
  const bool dragChanged =
      drag.has_value() != m_drag.has_value() ||
      (drag && (drag->index != m_drag->index || drag->position != m_drag->position));
  if (pointsChanged || dragChanged || settings.markerPixels != m_markerPixels) {
    m_markerInstances.clear();
    const auto& points = document->points();
    for (std::size_t i = 0; i < points.size(); ++i) {
      MarkerInstance m;
      const bool dragged = drag && drag->index == static_cast<int>(i);
      m.position = dragged ? drag->position : document->toView(points[i].position);
      const bool selected = document->selected() == static_cast<int>(i);
      m.radiusPixels = settings.markerPixels * (selected ? 1.35f : 1.0f);
      const Eigen::Vector3f c = typeColor(points[i].type);
      m.color = Eigen::Vector4f(c.x(), c.y(), c.z(), 1.0f);
      m_markerInstances.push_back(m);
    }
    m_markers.upload(m_markerInstances);
    m_revision = document->revision();
    m_drag = drag;
    m_markerPixels = settings.markerPixels;
  }
}

void SceneRenderer::draw(const Camera& camera, const ViewSettings& settings) const {
  if (!m_document) return;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  if (settings.showMesh)
    m_mesh.draw(camera, settings.wireframe, settings.surface);
  m_field.draw(camera, settings.field);
  m_grid.draw(camera, settings.showGrid, settings.showAxes);
  if (settings.showPoints) m_markers.draw(camera);
  glDisable(GL_DEPTH_TEST);
}

}  // namespace sagrid::ui
