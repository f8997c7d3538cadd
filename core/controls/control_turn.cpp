#include "core/controls/control_turn.h"

#include <Eigen/Geometry>

#include "core/mesh/triangle_subset.h"

namespace sagrid {

Eigen::Vector3f movedWithControl(const ControlPart& part, const Eigen::Vector3f& p, float angle, float press) {
  const Eigen::Vector3f axis = part.axis.normalized();
  if (!isHinge(part.motion)) return p + press * axis;
  return part.pivot + Eigen::AngleAxisf(angle, axis) * (p - part.pivot);
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
    const Eigen::Matrix3f turn = Eigen::AngleAxisf(angle, part.axis.normalized()).toRotationMatrix();
    for (std::size_t v = 0; v < moved.positions.size(); ++v) {
      moved.positions[v] = movedWithControl(part, moved.positions[v], angle, press);
      if (isHinge(part.motion) && v < moved.normals.size()) moved.normals[v] = turn * moved.normals[v];
    }
    out.append(moved);  // its materials (and textures) come along, as copies
  }
  return out;
}

}  // namespace sagrid
