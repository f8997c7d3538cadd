// The signed volume a triangle mesh encloses (divergence theorem): positive when its triangles
// face outwards. For open meshes only a hint of the winding.
#pragma once

#include "core/mesh/mesh.h"

namespace sagrid::physics {

inline double signedVolume(const Mesh& mesh) {
  double sixTimes = 0;
  for (const auto& t : mesh.triangles)
    sixTimes += mesh.positions[t[0]].cast<double>().dot(
        mesh.positions[t[1]].cast<double>().cross(mesh.positions[t[2]].cast<double>()));
  return sixTimes / 6.0;
}

}  // namespace sagrid::physics
