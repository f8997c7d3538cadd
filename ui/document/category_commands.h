// The object's category as the curator switches it (stove, sink, none, ...): labels.json
// object.category, an undoable edit like every other. Session::switchCategory pairs it with
// dropping the old category's predicted points, in one undo step.
#pragma once

#include <string>

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

}  // namespace sagrid::ui
