#include "ui/document/point_commands.h"

#include <utility>
#include <vector>

#include "core/common/error.h"

namespace sagrid::ui {

namespace {
AffordancePoint& pointAt(ObjectLabels& labels, int index) {
  if (index < 0 || index >= static_cast<int>(labels.affordances.size())) {
    throw InvalidArgument("no affordance point #" + std::to_string(index + 1));
  }
  return labels.affordances[static_cast<std::size_t>(index)];
}
}  // namespace

MovePointCommand::MovePointCommand(int index, Eigen::Vector3f position,
                                   std::optional<Eigen::Vector3f> normal, std::string description)
    : m_index(index),
      m_position(std::move(position)),
      m_normal(std::move(normal)),
      m_description(std::move(description)) {}

void MovePointCommand::apply(ObjectLabels& labels) {
  AffordancePoint& p = pointAt(labels, m_index);
  m_before = p;
  p.position = m_position;
  if (m_normal) p.normal = m_normal;
  if (p.status != AffordanceStatus::Added) p.status = AffordanceStatus::Edited;
  p.source = "human";
}

void MovePointCommand::revert(ObjectLabels& labels) { pointAt(labels, m_index) = m_before; }

std::unique_ptr<Command> makeSetCoordinatesCommand(int index, const Eigen::Vector3f& position) {
  return std::make_unique<MovePointCommand>(index, position, std::nullopt, "Set coordinates");
}

AddPointCommand::AddPointCommand(AffordancePoint point, CurationAction action)
    : m_point(std::move(point)), m_action(action) {
  m_point.status = AffordanceStatus::Added;
  m_point.source = "human";
  m_point.confidence.reset();
}

void AddPointCommand::apply(ObjectLabels& labels) {
  labels.affordances.push_back(m_point);
  m_index = static_cast<int>(labels.affordances.size()) - 1;
}

void AddPointCommand::revert(ObjectLabels& labels) {
  labels.affordances.erase(labels.affordances.begin() + m_index);
}

void DeletePointCommand::apply(ObjectLabels& labels) {
  m_point = pointAt(labels, m_index);
  labels.affordances.erase(labels.affordances.begin() + m_index);
}

void DeletePointCommand::revert(ObjectLabels& labels) {
  labels.affordances.insert(labels.affordances.begin() + m_index, m_point);
}

void AcceptPointCommand::apply(ObjectLabels& labels) {
  AffordancePoint& p = pointAt(labels, m_index);
  m_before = p.status;
  m_sourceBefore = p.source;
  p.status = AffordanceStatus::Accepted;
}

void AcceptPointCommand::revert(ObjectLabels& labels) {
  AffordancePoint& p = pointAt(labels, m_index);
  p.status = m_before;
  p.source = m_sourceBefore;
}

void ChangeTypeCommand::apply(ObjectLabels& labels) {
  AffordancePoint& p = pointAt(labels, m_index);
  m_before = p;
  p.type = m_type;
  if (p.status != AffordanceStatus::Added) p.status = AffordanceStatus::Edited;
}

void ChangeTypeCommand::revert(ObjectLabels& labels) { pointAt(labels, m_index) = m_before; }

std::unique_ptr<CommandGroup> makeAcceptAllCommand(const ObjectLabels& labels) {
  std::vector<std::unique_ptr<Command>> children;
  for (std::size_t i = 0; i < labels.affordances.size(); ++i) {
    if (labels.affordances[i].status == AffordanceStatus::Predicted) {
      children.push_back(std::make_unique<AcceptPointCommand>(static_cast<int>(i)));
    }
  }
  return std::make_unique<CommandGroup>("Accept all points", std::move(children));
}

}  // namespace sagrid::ui
