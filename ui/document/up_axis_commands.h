// Undoable commands behind "turn up axis": turning the object to another file up axis (the view
// mesh turns, labels' object.up changes, predicted points of the old axis are dropped so a new
// prediction can fill them) and adopting predicted points as an edit when the history must stay
// undoable (after a turn).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "ui/document/command.h"

namespace sagrid::ui {

class AnnotationDocument;

class TurnUpAxisCommand final : public Command {
 public:
  TurnUpAxisCommand(AnnotationDocument& document, UpAxis to);
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override;

 private:
  AnnotationDocument& m_document;
  UpAxis m_to, m_from = UpAxis::Z;
  std::string m_upBefore;
  std::optional<double> m_confidenceBefore;
  std::vector<AffordancePoint> m_pointsBefore;
};

// Sets all points to `points` (e.g. a prediction); revert restores the previous ones.
class ReplacePointsCommand final : public Command {
 public:
  ReplacePointsCommand(std::vector<AffordancePoint> points, std::string description);
  void apply(ObjectLabels& labels) override;
  void revert(ObjectLabels& labels) override;
  std::string description() const override { return m_description; }

 private:
  std::vector<AffordancePoint> m_after, m_before;
  std::string m_description;
};

}  // namespace sagrid::ui
