#include "core/points/part_ownership.h"

#include <algorithm>
#include <map>
#include <optional>

namespace sagrid {

namespace {
using PartOf = std::vector<std::vector<std::optional<std::size_t>>>;  // per type, per point

void keepWhere(TypedPoints& typed, std::vector<std::optional<std::size_t>>& partOf,
               const std::vector<bool>& keep) {
  std::vector<ExtractedPoint> points;
  std::vector<std::optional<std::size_t>> parts;
  for (std::size_t i = 0; i < typed.points.size(); ++i)
    if (keep[i]) points.push_back(typed.points[i]), parts.push_back(partOf[i]);
  typed.points = std::move(points);
  partOf = std::move(parts);
}

// Knob points on a large part go when the type has points on small parts.
void dropOnLargeParts(TypedPoints& typed, std::vector<std::optional<std::size_t>>& partOf,
                      const std::vector<ConnectedPart>& parts, float touch, float reach,
                      const PartOwnershipSettings& settings) {
  const bool anyOnPart =
      std::any_of(partOf.begin(), partOf.end(), [](const auto& part) { return part.has_value(); });
  if (!typed.ownParts || !anyOnPart) return;
  std::vector<bool> keep(partOf.size());
  for (std::size_t i = 0; i < partOf.size(); ++i) {
    const auto under = partAt(typed.points[i].position, parts, touch);
    keep[i] =
        partOf[i] || !under || parts[*under].box.diagonal().norm() <= settings.largePartDiagonal;
    if (keep[i]) continue;
    // A knob point beside a knob no point of its type lies on moves onto it.
    const auto free = partAt(typed.points[i].position, parts, reach, settings.maxPartDiagonal);
    if (!free || std::find(partOf.begin(), partOf.end(), free) != partOf.end()) continue;
    typed.points[i].position = parts[*free].centroid;
    partOf[i] = free;
    keep[i] = true;
  }
  keepWhere(typed, partOf, keep);
}
}  // namespace

std::vector<TypedPoints> ownParts(std::vector<TypedPoints> byType,
                                  const std::vector<ConnectedPart>& parts, int resolution,
                                  const PartOwnershipSettings& settings) {
  if (parts.empty() || resolution <= 0) return byType;
  const float touch = settings.touchVoxels / static_cast<float>(resolution);
  const float reach = settings.reachVoxels / static_cast<float>(resolution);
  PartOf partOf(byType.size());
  for (std::size_t t = 0; t < byType.size(); ++t) {
    for (const auto& point : byType[t].points)
      partOf[t].push_back(partAt(point.position, parts, touch, settings.maxPartDiagonal));
    dropOnLargeParts(byType[t], partOf[t], parts, touch, reach, settings);
  }
  // The owner of each small part that holds points: the type of its most confident point.
  std::map<std::size_t, std::pair<std::size_t, float>> owner;  // part -> (type, confidence)
  for (std::size_t t = 0; t < byType.size(); ++t)
    for (std::size_t i = 0; i < byType[t].points.size(); ++i) {
      if (!partOf[t][i]) continue;
      const float confidence = byType[t].points[i].confidence;
      auto [it, added] = owner.try_emplace(*partOf[t][i], t, confidence);
      if (!added && confidence > it->second.second) it->second = {t, confidence};
    }
  for (std::size_t t = 0; t < byType.size(); ++t) {
    const auto& points = byType[t].points;
    std::vector<bool> keep(points.size());
    for (std::size_t i = 0; i < keep.size(); ++i)
      keep[i] = !partOf[t][i] || owner.at(*partOf[t][i]).first == t;
    // Every type of the category has an instance: a type that would lose all its points keeps
    // its most confident one.
    if (!points.empty() && std::none_of(keep.begin(), keep.end(), [](bool k) { return k; }))
      keep[std::max_element(points.begin(), points.end(),
                            [](const ExtractedPoint& a, const ExtractedPoint& b) {
                              return a.confidence < b.confidence;
                            }) -
           points.begin()] = true;
    keepWhere(byType[t], partOf[t], keep);
  }
  return byType;
}

}  // namespace sagrid
