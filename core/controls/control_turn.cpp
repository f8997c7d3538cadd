#include "core/controls/control_turn.h"

#include <Eigen/Geometry>

#include "core/mesh/triangle_subset.h"

namespace sagrid {

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
    const Eigen::Vector3f axis = part.axis.normalized();
    const Eigen::Matrix3f turn = Eigen::AngleAxisf(angle, axis).toRotationMatrix();
    for (std::size_t v = 0; v < moved.positions.size(); ++v) {
      Eigen::Vector3f& p = moved.positions[v];
      if (isHinge(part.motion)) {
        p = part.pivot + turn * (p - part.pivot);
        if (v < moved.normals.size()) moved.normals[v] = turn * moved.normals[v];
      } else {
        p += press * axis;
      }
    }
    out.append(moved);  // its materials (and textures) come along, as copies
  }
  return out;
}

}  // namespace sagrid
