// The object's category as the curator switches it (stove, sink, none, ...): labels.json
// object.category, an undoable edit like every other. Session::switchCategory pairs it with
// dropping the old category's predicted points, in one undo step. For a rejected object with
// suggested points (core/annotate/suggested_points.h) the curator takes the suggested category
// with them (C), or keeps "none" and drops them (accepting the object).
#pragma once

#include <memory>
#include <string>

#include "core/annotate/suggested_points.h"
#include "ui/document/command.h"

namespace sagrid::ui {

class SetCategoryCommand final : public Command {
 public:
  // `action`: how the curation log counts it (the list, or the category's key).
  explicit SetCategoryCommand(std::string category, CurationAction action = CurationAction::Category)
      : m_category(std::move(category)), m_action(action) {}
  void apply(ObjectLabels& labels) override {
    m_before = labels.object.category;
    labels.object.category = m_category;
  }
  void revert(ObjectLabels& labels) override { labels.object.category = m_before; }
  std::string description() const override { return "Category " + m_category; }
  CurationAction curationAction() const override { return m_action; }

 private:
  std::string m_category;
  CurationAction m_action;
  std::string m_before;
};

// A rejected object's suggestions settled (core/annotate/suggested_points.h): `settle` is
// confirmSuggestions (C: the suggested category becomes the object's, its points ordinary
// predictions) or dropSuggestions (A on "none": the suggested points go). Undo restores them.
class SettleSuggestionsCommand final : public Command {
 public:
  using Settle = void (*)(ObjectLabels&);
  static std::unique_ptr<SettleSuggestionsCommand> confirm() {
    return std::make_unique<SettleSuggestionsCommand>(confirmSuggestions, "Take the suggested category",
                                                      CurationAction::ConfirmCategory);
  }
  static std::unique_ptr<SettleSuggestionsCommand> drop() {
    return std::make_unique<SettleSuggestionsCommand>(dropSuggestions, "Drop the suggested points",
                                                      CurationAction::Delete);
  }
  SettleSuggestionsCommand(Settle settle, std::string description, CurationAction action)
      : m_settle(settle), m_description(std::move(description)), m_action(action) {}
  void apply(ObjectLabels& labels) override {
    m_before = labels;
    m_settle(labels);
  }
  void revert(ObjectLabels& labels) override { labels = m_before; }
  std::string description() const override { return m_description; }
  CurationAction curationAction() const override { return m_action; }

 private:
  Settle m_settle;
  std::string m_description;
  CurationAction m_action;
  ObjectLabels m_before;
};

}  // namespace sagrid::ui
