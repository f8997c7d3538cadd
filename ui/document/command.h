// The command pattern behind every user edit: a Command changes the AnnotationDocument's labels
// in apply() and puts them back exactly in revert(). Panels and input handlers never touch the
// labels directly; they build a command and hand it to AnnotationDocument::execute(), which keeps
// the undo/redo history and autosaves.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/curation/curation_log.h"
#include "core/labels/labels.h"

namespace sagrid::ui {

class Command {
 public:
  virtual ~Command() = default;
  virtual void apply(ObjectLabels& labels) = 0;
  virtual void revert(ObjectLabels& labels) = 0;
  virtual std::string description() const = 0;
  // Index of the point to select after apply (-1: leave the selection alone).
  virtual int selectionAfterApply() const { return -1; }
  virtual int selectionAfterRevert() const { return -1; }
  // What the curation log calls this edit (core/curation/curation_log.h).
  virtual CurationAction curationAction() const { return CurationAction::Edit; }
};

// Applies children in order and reverts them in reverse: one undo step for many changes.
class CommandGroup final : public Command {
 public:
  // `action`: what the log calls the group when it is not its first child's action.
  CommandGroup(std::string description, std::vector<std::unique_ptr<Command>> children,
               std::optional<CurationAction> action = std::nullopt);
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override { return m_description; }
  // A group is the action of its children (accepting every point is many accepts, one step).
  CurationAction curationAction() const override {
    if (m_action) return *m_action;
    return m_children.empty() ? CurationAction::Edit : m_children.front()->curationAction();
  }
  bool empty() const { return m_children.empty(); }

 private:
  std::string m_description;
  std::vector<std::unique_ptr<Command>> m_children;
  std::optional<CurationAction> m_action;
};

// Undo/redo history. Executing a new command drops the redo branch.
class CommandStack {
 public:
  // Applies `command` and records it.
  void execute(std::unique_ptr<Command> command, ObjectLabels& labels);
  bool canUndo() const { return m_next > 0; }
  bool canRedo() const { return m_next < m_history.size(); }
  // Return the command that was undone/redone (nullptr if none), for selection and messages.
  const Command* undo(ObjectLabels& labels);
  const Command* redo(ObjectLabels& labels);
  std::string undoDescription() const;
  std::string redoDescription() const;
  std::size_t size() const { return m_history.size(); }
  std::size_t applied() const { return m_next; }  // commands applied (the rest can be redone)

 private:
  std::vector<std::unique_ptr<Command>> m_history;
  std::size_t m_next = 0;  // commands [0, m_next) are applied
};

}  // namespace sagrid::ui
