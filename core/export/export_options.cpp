#include "core/export/export_options.h"

namespace sagrid {

std::optional<CollisionMode> parseCollisionMode(const std::string& text) {
  if (text == "none") return CollisionMode::None;
  if (text == "hull") return CollisionMode::Hull;
  if (text == "decompose") return CollisionMode::Decompose;
  return std::nullopt;
}

const char* toString(CollisionMode mode) {
  switch (mode) {
    case CollisionMode::None:
      return "none";
    case CollisionMode::Hull:
      return "hull";
    case CollisionMode::Decompose:
      return "decompose";
  }
  return "decompose";
}

}  // namespace sagrid
