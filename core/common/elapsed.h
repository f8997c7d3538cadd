// Wall time since a moment, in seconds, for progress lines, timings in reports and budgets.
#pragma once

#include <chrono>

namespace sagrid {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace sagrid
