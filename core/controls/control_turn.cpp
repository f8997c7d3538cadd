#include "core/controls/control_turn.h"

#include <algorithm>

#include "core/mesh/triangle_subset.h"

namespace sagrid {

Eigen::Affine3f controlMotion(const ControlPart& part, float angle, float press) {
  const Eigen::Vector3f axis = part.axis.normalized();
  Eigen::Affine3f motion = Eigen::Affine3f::Identity();
  if (!isHinge(part.motion)) return motion.translate(press * axis);
  return motion.translate(part.pivot).rotate(Eigen::AngleAxisf(angle, axis)).translate(-part.pivot);
}

float pressAtTurn(float angle, double metersPerUnit) {
  return angle == 0.0f ? 0.0f : static_cast<float>(kButtonTravel / std::max(metersPerUnit, 1e-9));
}

Mesh turnControls(const Mesh& mesh, const std::vector<ControlPart>& parts, float angle,
                  float press) {
  std::vector<bool> body(mesh.triangles.size(), true);
  for (const auto& part : parts)
    for (int t : part.triangles)
      if (t >= 0 && static_cast<std::size_t>(t) < body.size()) body[static_cast<std::size_t>(t)] = false;
  Mesh out = triangleSubset(mesh, body);
  for (const auto& part : parts) {
    if (part.triangles.empty()) continue;
    std::vector<bool> keep(mesh.triangles.size(), false);
    for (int t : part.triangles)
      if (t >= 0 && static_cast<std::size_t>(t) < keep.size()) keep[static_cast<std::size_t>(t)] = true;
    Mesh moved = triangleSubset(mesh, keep);
    const Eigen::Affine3f motion = controlMotion(part, angle, press);
    for (auto& p : moved.positions) p = motion * p;
    for (auto& n : moved.normals) n = motion.linear() * n;
    out.append(moved);  // its materials (and textures) come along, as copies
  }
  return out;
}

}  // namespace sagrid
