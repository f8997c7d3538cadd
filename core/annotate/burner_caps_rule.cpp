#include "core/annotate/burner_caps_rule.h"

#include "core/geometry/connected_parts.h"
#include "core/mesh/mesh.h"
#include "core/points/repeated_parts.h"

namespace sagrid {

bool hasBurnerCaps(const Mesh& mesh, const BurnerCapRule& rule) {
  Eigen::AlignedBox3f bounds;
  for (const auto& p : mesh.positions) bounds.extend(p);
  if (bounds.isEmpty()) return false;
  const float minWidth = rule.minDiameterShare * bounds.sizes().maxCoeff();
  const auto parts = connectedParts(mesh);
  const auto isCap = [&](const ConnectedPart& part) {
    return part.triangles >= kMinInstanceTriangles && isRoundFlatPart(part) &&
           part.box.sizes().head<2>().maxCoeff() >= minWidth;
  };
  const PartCopies copies(parts, kCopyTolerance);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (!isCap(parts[p])) continue;
    int caps = 1;
    for (std::size_t q : copies.of(p)) caps += isCap(parts[q]) ? 1 : 0;
    if (caps >= rule.minCaps) return true;
  }
  return false;
}

CategoryDecision withBurnerCaps(const CategoryDecision& decision, const std::function<Mesh()>& mesh,
                                const BurnerCapRule& rule) {
  if (decision.rejected || decision.category != "sink" || !hasBurnerCaps(mesh(), rule))
    return decision;
  CategoryDecision out = decision;
  out.category = out.best = "stove";
  out.byBurnerCaps = true;
  return out;
}

}  // namespace sagrid
