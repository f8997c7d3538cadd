#include "ui/document/command.h"

#include <utility>

namespace sagrid::ui {

CommandGroup::CommandGroup(std::string description, std::vector<std::unique_ptr<Command>> children,
                           std::optional<CurationAction> action)
    : m_description(std::move(description)), m_children(std::move(children)), m_action(action) {}

void CommandGroup::apply(ObjectLabels& labels) {
  for (auto& child : m_children) child->apply(labels);
}

void CommandGroup::revert(ObjectLabels& labels) {
  for (auto it = m_children.rbegin(); it != m_children.rend(); ++it) (*it)->revert(labels);
}

void CommandStack::execute(std::unique_ptr<Command> command, ObjectLabels& labels) {
  command->apply(labels);
  m_history.resize(m_next);
  m_history.push_back(std::move(command));
  m_next = m_history.size();
}

const Command* CommandStack::undo(ObjectLabels& labels) {
  if (!canUndo()) return nullptr;
  Command* command = m_history[--m_next].get();
  command->revert(labels);
  return command;
}

const Command* CommandStack::redo(ObjectLabels& labels) {
  if (!canRedo()) return nullptr;
  Command* command = m_history[m_next++].get();
  command->apply(labels);
  return command;
}

std::string CommandStack::undoDescription() const {
  return canUndo() ? m_history[m_next - 1]->description() : std::string();
}

std::string CommandStack::redoDescription() const {
  return canRedo() ? m_history[m_next]->description() : std::string();
}

}  // namespace sagrid::ui
