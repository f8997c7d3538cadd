// Access to the GLSL sources of shaders/, embedded into the binary at build time.
#pragma once

#include <string_view>

namespace sagrid::ui {

// The source of shaders/<fileName>; throws sagrid::Error if no such shader was embedded.
std::string_view shaderSource(std::string_view fileName);

}  // namespace sagrid::ui
