#include "support/curation_counts.h"

#include <algorithm>

namespace sagrid::test {

std::size_t countOfType(const std::vector<AffordancePoint>& points, const std::string& type) {
  return static_cast<std::size_t>(std::count_if(
      points.begin(), points.end(), [&](const AffordancePoint& p) { return p.type == type; }));
}

std::ptrdiff_t loggedActions(const std::filesystem::path& log, CurationAction action) {
  const auto events = readCurationLog(log);
  return std::count_if(events.begin(), events.end(),
                       [&](const CurationEvent& e) { return e.action == action; });
}

}  // namespace sagrid::test
