#include "core/common/json_number.h"

#include <cstdio>
#include <cstdlib>

namespace sagrid {

double jsonNumber(float value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.7g", static_cast<double>(value));
  return std::strtod(buffer, nullptr);
}

}  // namespace sagrid
