#include "ui/document/control_view.h"

#include "core/common/error.h"
#include "core/controls/control_record.h"
#include "ui/document/annotation_document.h"

namespace sagrid::ui {

namespace {

// The parts found for one revision of one document.
struct FoundCache {
  const AnnotationDocument* document = nullptr;
  std::uint64_t revision = 0;
  std::vector<int> toggles;  // point indices
  ControlParts found;
};

const FoundCache& foundFor(const AnnotationDocument& document) {
  static FoundCache cache;
  if (cache.document == &document && cache.revision == document.revision()) return cache;
  cache = FoundCache{&document, document.revision(), {}, {}};
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < static_cast<int>(document.points().size()); ++i) {
    if (document.points()[std::size_t(i)].type != "togglebutton") continue;
    cache.toggles.push_back(i);
    points.push_back(document.pointInView(i));
  }
  cache.found = findControlParts(document.mesh(), points);
  return cache;
}

}  // namespace

std::optional<ShownControl> shownControl(const AnnotationDocument& document, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= document.points().size()) return std::nullopt;
  const AffordancePoint& point = document.points()[std::size_t(index)];
  if (point.type != "togglebutton") return std::nullopt;
  try {
    if (auto record = readControlRecord(point, document.mesh().fileUp, document.labelsPath()))
      return ShownControl{record->part, true, record->drives, {}};
  } catch (const Error&) {
    // A malformed record: shown as found, and the exports will say what is wrong with it.
  }
  const FoundCache& cache = foundFor(document);
  for (std::size_t k = 0; k < cache.toggles.size(); ++k) {
    if (cache.toggles[k] != index) continue;
    if (!cache.found.parts[k]) return std::nullopt;
    return ShownControl{*cache.found.parts[k], false, std::nullopt, cache.found.warnings[k]};
  }
  return std::nullopt;
}

}  // namespace sagrid::ui
