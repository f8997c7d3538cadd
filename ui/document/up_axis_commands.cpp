#include "ui/document/up_axis_commands.h"

#include <algorithm>

#include "core/mesh/mesh_import.h"
#include "ui/document/annotation_document.h"

namespace sagrid::ui {

TurnUpAxisCommand::TurnUpAxisCommand(AnnotationDocument& document, UpAxis to)
    : m_document(document), m_to(to) {}

void TurnUpAxisCommand::apply(ObjectLabels& labels) {
  m_from = m_document.mesh().fileUp;
  m_upBefore = labels.object.up;
  m_confidenceBefore = labels.object.upConfidence;
  m_pointsBefore = labels.affordances;
  m_document.setMeshUpAxis(m_to);
  labels.object.up = toString(m_to);
  labels.object.upConfidence.reset();  // chosen by the curator, not detected
  // Predicted points were placed for the old up axis; reviewed ones are the curator's and stay.
  auto& points = labels.affordances;
  points.erase(std::remove_if(points.begin(), points.end(),
                              [](const AffordancePoint& p) {
                                return p.status == AffordanceStatus::Predicted;
                              }),
               points.end());
}

void TurnUpAxisCommand::revert(ObjectLabels& labels) {
  m_document.setMeshUpAxis(m_from);
  labels.object.up = m_upBefore;
  labels.object.upConfidence = m_confidenceBefore;
  labels.affordances = m_pointsBefore;
}

std::string TurnUpAxisCommand::description() const {
  return std::string("turn up axis to ") + toString(m_to);
}

ReplacePointsCommand::ReplacePointsCommand(std::vector<AffordancePoint> points,
                                           std::string description)
    : m_after(std::move(points)), m_description(std::move(description)) {}

void ReplacePointsCommand::apply(ObjectLabels& labels) {
  m_before = labels.affordances;
  labels.affordances = m_after;
}

void ReplacePointsCommand::revert(ObjectLabels& labels) { labels.affordances = m_before; }

}  // namespace sagrid::ui
