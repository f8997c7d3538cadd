// One number in a Markdown report table: printf-formatted, or "–" when it is not finite (a
// missing measurement, e.g. a type no object has).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace sagrid {

inline std::string reportCell(double value, const char* format) {
  if (!std::isfinite(value)) return "–";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

}  // namespace sagrid
