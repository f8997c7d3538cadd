#include "core/annotate/burner_caps_rule.h"

#include <algorithm>

#include "core/geometry/connected_parts.h"
#include "core/mesh/mesh.h"

namespace sagrid {

std::vector<RoundFlatFamily> roundFlatFamilies(const Mesh& mesh) {
  Eigen::AlignedBox3f bounds;
  for (const auto& p : mesh.positions) bounds.extend(p);
  if (bounds.isEmpty() || !(bounds.sizes().maxCoeff() > 0)) return {};
  const float extent = bounds.sizes().maxCoeff();
  const auto parts = connectedParts(mesh);
  const auto isRoundFlat = [](const ConnectedPart& part) {
    return part.triangles >= kMinInstanceTriangles && isRoundFlatPart(part);
  };
  const auto widthShare = [extent](const ConnectedPart& part) {
    return part.box.sizes().head<2>().maxCoeff() / extent;
  };
  const PartCopies copies(parts, kCopyTolerance);
  std::vector<RoundFlatFamily> out;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (!isRoundFlat(parts[p])) continue;
    RoundFlatFamily family{p, {widthShare(parts[p])}};
    for (std::size_t q : copies.of(p))
      if (isRoundFlat(parts[q])) family.widthShares.push_back(widthShare(parts[q]));
    out.push_back(std::move(family));
  }
  return out;
}

bool hasBurnerCaps(const Mesh& mesh, const BurnerCapRule& rule) {
  for (const auto& family : roundFlatFamilies(mesh)) {
    const auto wide = [&rule](float share) { return share >= rule.minDiameterShare; };
    if (wide(family.widthShares.front()) &&
        std::count_if(family.widthShares.begin(), family.widthShares.end(), wide) >= rule.minCaps)
      return true;
  }
  return false;
}

CategoryDecision withBurnerCaps(const CategoryDecision& decision,
                                const std::function<bool()>& hasCaps) {
  if (decision.rejected || decision.category != "sink" || !hasCaps()) return decision;
  CategoryDecision out = decision;
  out.category = out.best = "stove";
  out.byBurnerCaps = true;
  return out;
}

}  // namespace sagrid
