#include "ui/document/mass_estimate.h"

#include <cstdint>

#include "core/common/error.h"
#include "ui/document/annotation_document.h"

namespace sagrid::ui {

const physics::MassProperties* MassEstimate::forDocument(const AnnotationDocument& document) {
  const Mesh& mesh = document.mesh();
  const std::string key = mesh.sha256 + "|" + std::to_string(mesh.triangleCount()) + "|" +
                          std::to_string(document.metersPerUnit()) + "|" +
                          document.labels().object.category + "|" +
                          std::to_string(reinterpret_cast<std::uintptr_t>(&mesh));
  if (key != m_key) {
    m_key = key;
    m_estimate.reset();
    m_error.clear();
    try {
      physics::MassOptions options;
      options.metersPerUnit = document.metersPerUnit();
      options.category = document.labels().object.category;
      m_estimate = physics::estimateMassProperties(mesh, options);
    } catch (const Error& e) {
      m_error = e.what();
    }
  }
  return m_estimate ? &*m_estimate : nullptr;
}

}  // namespace sagrid::ui
