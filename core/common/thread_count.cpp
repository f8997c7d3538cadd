#include "core/common/thread_count.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <thread>

namespace sagrid {

int defaultThreadCount() {
  static const int count = [] {
    if (const char* value = std::getenv("SAGRID_THREADS")) {
      try {
        const int requested = std::stoi(value);
        if (requested > 0) return requested;
      } catch (const std::exception&) {
        // Not a number: fall back to the hardware count.
      }
    }
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  }();
  return count;
}

}  // namespace sagrid
