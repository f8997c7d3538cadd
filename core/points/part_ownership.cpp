#include "core/points/part_ownership.h"

#include <algorithm>
#include <limits>
#include <map>
#include <optional>

namespace sagrid {

namespace {
using PartOf = std::vector<std::vector<std::optional<std::size_t>>>;  // per type, per point
// The owner of a small part: the type of its most confident point.
struct Owner {
  std::size_t type;
  float confidence;
  bool fullRow;  // the type has a point on every copy of the part
  // A type with a point on every knob of a row owns them over a surer point of another type (a
  // burner point on two knobs of a range's seven).
  bool beats(const Owner& other) const {
    return fullRow != other.fullRow ? fullRow : confidence > other.confidence;
  }
};
using Owners = std::map<std::size_t, Owner>;  // by small part

void keepWhere(TypedPoints& typed, std::vector<std::optional<std::size_t>>& partOf,
               const std::vector<bool>& keep) {
  std::vector<ExtractedPoint> points;
  std::vector<std::optional<std::size_t>> parts;
  for (std::size_t i = 0; i < typed.points.size(); ++i)
    if (keep[i]) points.push_back(typed.points[i]), parts.push_back(partOf[i]);
  typed.points = std::move(points);
  partOf = std::move(parts);
}

// A type never loses all its points to a rule: without any kept, its most confident one stays.
void keepOneAtLeast(const std::vector<ExtractedPoint>& points, std::vector<bool>& keep) {
  if (points.empty() || std::any_of(keep.begin(), keep.end(), [](bool k) { return k; })) return;
  keep[std::max_element(points.begin(), points.end(),
                        [](const ExtractedPoint& a, const ExtractedPoint& b) {
                          return a.confidence < b.confidence;
                        }) -
       points.begin()] = true;
}

// Which parts are feet (PartOwnershipSettings::footHeight): standing on the lowest point of every
// part, within half a voxel, and no higher than footHeight above it. None when the rule is off.
std::vector<bool> feetOf(const std::vector<ConnectedPart>& parts, int resolution,
                         const PartOwnershipSettings& settings) {
  std::vector<bool> foot(parts.size(), false);
  if (settings.footHeight <= 0) return foot;
  float bottom = std::numeric_limits<float>::infinity();
  for (const auto& part : parts) bottom = std::min(bottom, part.box.min().z());
  const float standing = 0.5f / static_cast<float>(resolution);
  for (std::size_t p = 0; p < parts.size(); ++p)
    foot[p] = parts[p].box.min().z() <= bottom + standing &&
              parts[p].box.max().z() <= bottom + settings.footHeight;
  return foot;
}

// Points of a type with ownParts on a foot go, unless the type would lose its last.
void dropOnFeet(TypedPoints& typed, std::vector<std::optional<std::size_t>>& partOf,
                const std::vector<bool>& foot) {
  if (!typed.ownParts) return;
  std::vector<bool> keep(partOf.size());
  for (std::size_t i = 0; i < partOf.size(); ++i) keep[i] = !partOf[i] || !foot[*partOf[i]];
  keepOneAtLeast(typed.points, keep);
  keepWhere(typed, partOf, keep);
}

// Of a type with ownParts, one point per small part: the surest (the first on ties).
void onePointPerPart(TypedPoints& typed, std::vector<std::optional<std::size_t>>& partOf) {
  if (!typed.ownParts) return;
  std::map<std::size_t, std::size_t> surest;  // part -> point
  for (std::size_t i = 0; i < partOf.size(); ++i) {
    if (!partOf[i]) continue;
    auto [it, added] = surest.try_emplace(*partOf[i], i);
    if (!added && typed.points[i].confidence > typed.points[it->second].confidence) it->second = i;
  }
  std::vector<bool> keep(partOf.size());
  for (std::size_t i = 0; i < partOf.size(); ++i)
    keep[i] = !partOf[i] || surest.at(*partOf[i]) == i;
  keepWhere(typed, partOf, keep);
}

// Whether `family` (a part and its copies) is a full row: at least three members, each of which a
// point lies on (`partOf`: the parts a type's points lie on).
bool isFullRow(const std::vector<std::size_t>& family,
               const std::vector<std::optional<std::size_t>>& partOf) {
  return family.size() >= 3 && std::all_of(family.begin(), family.end(), [&](std::size_t member) {
           return std::find(partOf.begin(), partOf.end(), member) != partOf.end();
         });
}

// Every family of copies (at least three) each member of which a point lies on: a range's rows of
// knobs.
std::vector<std::vector<std::size_t>> fullRowsOf(
    const std::vector<std::optional<std::size_t>>& partOf, const PartCopies& copies) {
  std::vector<std::vector<std::size_t>> rows;
  for (const auto& part : partOf) {
    if (!part) continue;
    std::vector<std::size_t> family = copies.familyOf(*part);
    if (!isFullRow(family, partOf)) continue;
    std::sort(family.begin(), family.end());
    if (std::find(rows.begin(), rows.end(), family) == rows.end())
      rows.push_back(std::move(family));
  }
  return rows;
}

// How far from a full row's parts a point of its type may lie: strayRowSpacings x the row's
// spacing (the median distance from a member to the nearest other).
float rowReach(const std::vector<std::size_t>& row, const std::vector<ConnectedPart>& parts,
               const PartOwnershipSettings& settings) {
  std::vector<float> nearest;
  for (std::size_t member : row) nearest.push_back(nearestCentroidDistance(member, row, parts));
  std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
  return settings.strayRowSpacings * nearest[nearest.size() / 2];
}

// Points of a type with ownParts farther than strayRowSpacings x a row's spacing from every part of
// every full row go (a range with two rows of knobs keeps both).
void dropStrays(TypedPoints& typed, std::vector<std::optional<std::size_t>>& partOf,
                const std::vector<ConnectedPart>& parts, const PartCopies& copies,
                const PartOwnershipSettings& settings) {
  if (!typed.ownParts || settings.strayRowSpacings <= 0) return;
  const std::vector<std::vector<std::size_t>> rows = fullRowsOf(partOf, copies);
  if (rows.empty()) return;
  std::vector<float> reach;
  for (const auto& row : rows) reach.push_back(rowReach(row, parts, settings));
  std::vector<bool> keep(partOf.size(), false);
  for (std::size_t i = 0; i < partOf.size(); ++i)
    for (std::size_t r = 0; r < rows.size() && !keep[i]; ++r)
      keep[i] = std::any_of(rows[r].begin(), rows[r].end(), [&](std::size_t member) {
        return (typed.points[i].position - parts[member].centroid).norm() <= reach[r];
      });
  keepWhere(typed, partOf, keep);
}

// Points of a type with ownParts on a large part go (or move onto a free small part within reach)
// when the type has points on small parts.
void dropOnLargeParts(TypedPoints& typed, std::vector<std::optional<std::size_t>>& partOf,
                      std::size_t type, const Owners& owners,
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
    // A point beside a small part that no point of its type lies on and no other type owns moves
    // onto it.
    const auto free =
        partAt(typed.points[i].position, parts, reach, settings.contact.maxPartDiagonal);
    const auto owned = free ? owners.find(*free) : owners.end();
    if (!free || std::find(partOf.begin(), partOf.end(), free) != partOf.end() ||
        (owned != owners.end() && owned->second.type != type))
      continue;
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
  const float touch = settings.contact.touchVoxels / static_cast<float>(resolution);
  const float reach = settings.reachVoxels / static_cast<float>(resolution);
  PartOf partOf(byType.size());
  for (std::size_t t = 0; t < byType.size(); ++t) {
    for (const auto& point : byType[t].points)
      partOf[t].push_back(partAt(point.position, parts, touch, settings.contact.maxPartDiagonal));
  }
  const PartCopies copies(parts, kCopyTolerance);
  Owners owners;
  for (std::size_t t = 0; t < byType.size(); ++t)
    for (std::size_t i = 0; i < byType[t].points.size(); ++i) {
      if (!partOf[t][i]) continue;
      const Owner owner{t, byType[t].points[i].confidence,
                        byType[t].ownParts && isFullRow(copies.familyOf(*partOf[t][i]), partOf[t])};
      auto [it, added] = owners.try_emplace(*partOf[t][i], owner);
      if (!added && owner.beats(it->second)) it->second = owner;
    }
  for (std::size_t t = 0; t < byType.size(); ++t) {
    const auto& points = byType[t].points;
    std::vector<bool> keep(points.size());
    for (std::size_t i = 0; i < keep.size(); ++i)
      keep[i] = !partOf[t][i] || owners.at(*partOf[t][i]).type == t;
    // Every type of the category has an instance.
    keepOneAtLeast(points, keep);
    keepWhere(byType[t], partOf[t], keep);
  }
  const std::vector<bool> foot = feetOf(parts, resolution, settings);
  for (std::size_t t = 0; t < byType.size(); ++t) {
    dropOnLargeParts(byType[t], partOf[t], t, owners, parts, touch, reach, settings);
    dropOnFeet(byType[t], partOf[t], foot);
    if (settings.onePointPerPart) onePointPerPart(byType[t], partOf[t]);
    dropStrays(byType[t], partOf[t], parts, copies, settings);
  }
  return byType;
}

}  // namespace sagrid
