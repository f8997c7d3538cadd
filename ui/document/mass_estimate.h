// The estimated mass shown in the Object panel (core/physics: solid volume x the category's
// density), computed once per mesh, units and category rather than every frame.
#pragma once

#include <optional>
#include <string>

#include "core/physics/mass_properties.h"

namespace sagrid::ui {

class AnnotationDocument;

class MassEstimate {
 public:
  // The estimate for the open document, recomputed when its mesh, units or category changed;
  // nullptr when it cannot be computed (error() says why).
  const physics::MassProperties* forDocument(const AnnotationDocument& document);
  const std::string& error() const { return m_error; }

 private:
  std::string m_key;
  std::optional<physics::MassProperties> m_estimate;
  std::string m_error;
};

}  // namespace sagrid::ui
