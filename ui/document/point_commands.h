// The edits a curator makes to affordance points, one command each (see command.h). Positions
// are in the mesh file's own coordinates, as stored in labels.json.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

#include "ui/document/command.h"

namespace sagrid::ui {

// Moves point `index` to `position` (drag along the surface, or typed coordinates). The point
// becomes "edited" unless it was added by hand (it stays "added").
class MovePointCommand final : public Command {
 public:
  MovePointCommand(int index, Eigen::Vector3f position, std::optional<Eigen::Vector3f> normal,
                   std::string description = "Move point");
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override { return m_description; }
  CurationAction curationAction() const override { return CurationAction::Drag; }
  int selectionAfterApply() const override { return m_index; }
  int selectionAfterRevert() const override { return m_index; }

 private:
  int m_index;
  Eigen::Vector3f m_position;
  std::optional<Eigen::Vector3f> m_normal;
  std::string m_description;
  AffordancePoint m_before;
};

// Typed exact coordinates: a move with its own name in the history.
std::unique_ptr<Command> makeSetCoordinatesCommand(int index, const Eigen::Vector3f& position);

// Appends a point placed by hand (status "added", source "human").
class AddPointCommand final : public Command {
 public:
  // `action`: what the curation log calls it (Extend: the point one step past a row's end,
  // ui/document/point_row.h).
  explicit AddPointCommand(AffordancePoint point, CurationAction action = CurationAction::Add);
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override {
    return (m_action == CurationAction::Extend ? "Extend the row of " : "Add ") + m_point.type;
  }
  CurationAction curationAction() const override { return m_action; }
  int selectionAfterApply() const override { return m_index; }

 private:
  AffordancePoint m_point;
  CurationAction m_action;
  int m_index = -1;
};

class DeletePointCommand final : public Command {
 public:
  explicit DeletePointCommand(int index) : m_index(index) {}
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override { return "Delete " + m_point.type; }
  CurationAction curationAction() const override { return CurationAction::Delete; }
  int selectionAfterRevert() const override { return m_index; }

 private:
  int m_index;
  AffordancePoint m_point;
};

// Marks a point human-verified (status "accepted"); position and type are kept.
class AcceptPointCommand final : public Command {
 public:
  explicit AcceptPointCommand(int index) : m_index(index) {}
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override { return "Accept point"; }
  CurationAction curationAction() const override { return CurationAction::Accept; }
  int selectionAfterApply() const override { return m_index; }
  int selectionAfterRevert() const override { return m_index; }

 private:
  int m_index;
  AffordanceStatus m_before = AffordanceStatus::Predicted;
  std::string m_sourceBefore;
};

class ChangeTypeCommand final : public Command {
 public:
  ChangeTypeCommand(int index, std::string type) : m_index(index), m_type(std::move(type)) {}
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override { return "Change type to " + m_type; }
  CurationAction curationAction() const override { return CurationAction::Retype; }
  int selectionAfterApply() const override { return m_index; }
  int selectionAfterRevert() const override { return m_index; }

 private:
  int m_index;
  std::string m_type;
  AffordancePoint m_before;
};

// Accepts every point that is still "predicted" (one undo step); empty group when none is.
std::unique_ptr<CommandGroup> makeAcceptAllCommand(const ObjectLabels& labels);

}  // namespace sagrid::ui
