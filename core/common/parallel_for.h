// A minimal fork-join loop over [0, count) in contiguous chunks, one per worker thread (defaultThreadCount), for
// batches of independent queries (ray casts, closest points). Small counts run inline.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <thread>
#include <vector>

#include "core/common/thread_count.h"

namespace sagrid {

// On `threadCount` workers (at most; <= 0: defaultThreadCount). Use it for work whose items are
// independent: a result must not depend on how the range is cut (no float sums across chunks),
// or it will differ with the thread count.
inline void parallelFor(std::size_t count, std::size_t minParallelCount, int threadCount,
                        const std::function<void(std::size_t begin, std::size_t end)>& body) {
  const std::size_t threads = std::min<std::size_t>(
      static_cast<std::size_t>(threadCount > 0 ? threadCount : defaultThreadCount()),
      count / std::max<std::size_t>(1, minParallelCount / 2));
  if (count < minParallelCount || threads <= 1) {
    if (count > 0) body(0, count);
    return;
  }
  std::vector<std::thread> workers;
  const std::size_t chunk = (count + threads - 1) / threads;
  for (std::size_t t = 1; t < threads; ++t) {
    const std::size_t begin = t * chunk, end = std::min(count, begin + chunk);
    if (begin < end) workers.emplace_back(body, begin, end);
  }
  body(0, std::min(count, chunk));
  for (auto& w : workers) w.join();
}

inline void parallelFor(std::size_t count, std::size_t minParallelCount,
                        const std::function<void(std::size_t begin, std::size_t end)>& body) {
  parallelFor(count, minParallelCount, 0, body);
}

}  // namespace sagrid
