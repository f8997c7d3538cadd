#include "ui/document/control_view.h"

#include <map>

#include "core/common/error.h"
#include "core/controls/control_pairing.h"
#include "core/controls/control_record.h"
#include "core/controls/control_turn.h"
#include "ui/document/annotation_document.h"

namespace sagrid::ui {

namespace {

// The parts found for one labels revision of one document, and what was shown of each point
// (records parsed once per change of the labels, not once per frame or per selection).
struct FoundCache {
  const AnnotationDocument* document = nullptr;
  std::uint64_t revision = 0;
  std::filesystem::path labels;  // with the address: a new document at a freed one's address
  std::vector<int> toggles;  // point indices
  ControlParts found;
  // Per toggle point, the heat source its knob would light by the layout (as annotate pairs
  // them); empty where the object has no heat source.
  std::vector<int> drives;
  bool searched = false;     // `found` computed (only when a point has no record)
  std::map<int, std::optional<ShownControl>> shown;
};

FoundCache& cacheFor(const AnnotationDocument& document) {
  static FoundCache cache;
  if (cache.document != &document || cache.revision != document.labelsRevision() ||
      cache.labels != document.labelsPath()) {
    cache = FoundCache{};
    cache.document = &document;
    cache.revision = document.labelsRevision();
    cache.labels = document.labelsPath();
  }
  return cache;
}

const FoundCache& foundFor(const AnnotationDocument& document) {
  FoundCache& cache = cacheFor(document);
  if (cache.searched) return cache;
  cache.searched = true;
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < static_cast<int>(document.points().size()); ++i) {
    if (document.points()[std::size_t(i)].type != "togglebutton") continue;
    cache.toggles.push_back(i);
    points.push_back(document.pointInView(i));
  }
  cache.found = findControlParts(document.mesh(), points);
  cache.drives = pairToggleButtonsWithHeatSources(document.points(), document.mesh().fileUp);
  return cache;
}

std::optional<ShownControl> controlOf(const AnnotationDocument& document, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= document.points().size()) return std::nullopt;
  const AffordancePoint& point = document.points()[std::size_t(index)];
  if (point.type != "togglebutton") return std::nullopt;
  try {
    if (auto record = readControlRecord(point, document.mesh().fileUp, document.labelsPath()))
      return ShownControl{record->part, true, record->confirmed, record->drives, {}};
  } catch (const Error&) {
    // A malformed record: shown as found, and the exports will say what is wrong with it.
  }
  const FoundCache& cache = foundFor(document);
  for (std::size_t k = 0; k < cache.toggles.size(); ++k) {
    if (cache.toggles[k] != index) continue;
    if (!cache.found.parts[k]) return std::nullopt;
    const std::optional<int> drives =
        cache.drives.empty() ? std::nullopt : std::optional<int>(cache.drives[k]);
    return ShownControl{*cache.found.parts[k], false, false, drives, cache.found.warnings[k]};
  }
  return std::nullopt;
}

}  // namespace

std::optional<ShownControl> shownControl(const AnnotationDocument& document, int index) {
  FoundCache& cache = cacheFor(document);
  if (const auto it = cache.shown.find(index); it != cache.shown.end()) return it->second;
  const std::optional<ShownControl> shown = controlOf(document, index);
  cache.shown.emplace(index, shown);  // controlOf keeps `cache` (same revision)
  return shown;
}

Mesh meshWithControlsTurned(const AnnotationDocument& document, float angle) {
  std::vector<ControlPart> parts;
  const auto& points = document.points();
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    if (points[static_cast<std::size_t>(i)].type == "togglebutton")
      if (const auto shown = shownControl(document, i)) parts.push_back(shown->part);
  if (parts.empty() || angle == 0.0f) return document.mesh();
  return turnControls(document.mesh(), parts, angle, pressAtTurn(angle, sagrid::metersPerUnit(document.labels())));
}

}  // namespace sagrid::ui
