#include "core/annotate/touch_keys_pass.h"

#include "core/annotate/category_rules.h"
#include "core/grid/normalization.h"
#include "core/points/touch_keys.h"

namespace sagrid {

std::vector<PrintedCircle> touchKeysOf(const std::string& category,
                                       const std::vector<ConnectedPart>& parts,
                                       const SurfaceScene& scene,
                                       const Normalization& normalization, int resolution) {
  if (!categoryRulesFor(category).touchKeys) return {};
  std::vector<PrintedCircle> circles;
  for (const TouchKey& key : findTouchKeys(parts, scene, normalization, resolution))
    circles.push_back(
        {normalization.toMesh(key.centre), normalization.lengthToMesh(key.radius), 1.0f});
  return circles;
}

MarksForType touchKeysFor(const std::vector<PrintedCircle>& keys, const std::string& type) {
  if (type != "togglebutton" || keys.empty()) return {};
  return {keys, true};
}

}  // namespace sagrid
