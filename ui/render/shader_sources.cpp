#include "ui/render/shader_sources.h"

#include <string>
#include <utility>
#include <vector>

#include "core/common/error.h"

namespace sagrid::ui {

const std::vector<std::pair<std::string_view, std::string_view>>& embeddedShaders();

std::string_view shaderSource(std::string_view fileName) {
  for (const auto& [name, source] : embeddedShaders()) {
    if (name == fileName) return source;
  }
  throw Error("shader '" + std::string(fileName) + "' is not embedded (is it in shaders/?)");
}

}  // namespace sagrid::ui
