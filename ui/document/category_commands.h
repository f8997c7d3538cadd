// The object's category as the curator switches it (stove, sink, none, ...): labels.json
// object.category, an undoable edit like every other. Session::switchCategory pairs it with
// dropping the old category's predicted points, in one undo step. For a rejected object with
// suggested points (core/annotate/suggested_points.h) the curator takes the suggested category
// with them (C), or keeps "none" and drops them (accepting the object).
#pragma once

#include <string>

#include "core/annotate/suggested_points.h"
#include "ui/document/command.h"

namespace sagrid::ui {

class SetCategoryCommand final : public Command {
 public:
  explicit SetCategoryCommand(std::string category) : m_category(std::move(category)) {}
  void apply(ObjectLabels& labels) override {
    m_before = labels.object.category;
    labels.object.category = m_category;
  }
  void revert(ObjectLabels& labels) override { labels.object.category = m_before; }
  std::string description() const override { return "Category " + m_category; }
  CurationAction curationAction() const override { return CurationAction::Category; }

 private:
  std::string m_category;
  std::string m_before;
};

// Takes the suggested category: it becomes the object's and its points ordinary predictions.
class ConfirmSuggestionsCommand final : public Command {
 public:
  void apply(ObjectLabels& labels) override {
    m_before = labels;
    confirmSuggestions(labels);
  }
  void revert(ObjectLabels& labels) override { labels = m_before; }
  std::string description() const override { return "Take the suggested category"; }
  CurationAction curationAction() const override { return CurationAction::ConfirmCategory; }

 private:
  ObjectLabels m_before;
};

// Keeps "none": the suggested points go.
class DropSuggestionsCommand final : public Command {
 public:
  void apply(ObjectLabels& labels) override {
    m_before = labels;
    dropSuggestions(labels);
  }
  void revert(ObjectLabels& labels) override { labels = m_before; }
  std::string description() const override { return "Drop the suggested points"; }
  CurationAction curationAction() const override { return CurationAction::Delete; }

 private:
  ObjectLabels m_before;
};

}  // namespace sagrid::ui
