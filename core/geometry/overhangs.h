// Overhangs: surface points with open space below them down to another surface of the object — a
// spout's outlet over its basin, where water leaves a faucet. Found by walking vertical rays up
// through a neighbourhood and keeping, of each pair of successive hits, the upper one when the gap
// between them is open space (not the inside of a solid part: its middle is clear of the surface
// all round) and within a drop range. Works on the z-up mesh frame of a SurfaceScene.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sagrid {

class SurfaceScene;

struct Overhang {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();  // the underside hit, mesh frame
  float drop = 0;  // open height below it down to the next surface
  // Share of 8 rays tilted 35 degrees from straight up that leave the object from the landing
  // point below: a basin's bottom under a spout sees the sky, a cabinet's floor under the
  // countertop does not.
  float skyView = 0;
};

struct OverhangSearch {    // lengths in the scene's units
  float radius = 0;        // overhangs within this of the centre
  float step = 0;          // spacing of the vertical rays (a square lattice)
  float minDrop = 0;       // open height below an overhang, at least...
  float maxDrop = 0;       // ... and at most (a countertop over the floor is no outlet)
  float minClearance = 0;  // the gap's middle this far from every surface (the gap is open)
};

// Every overhang within `search.radius` of `centre`, in lattice
// order. Empty when a length is not positive or the lattice would exceed 40 000 rays.
std::vector<Overhang> overhangsNear(const SurfaceScene& scene, const Eigen::Vector3f& centre,
                                    const OverhangSearch& search);

}  // namespace sagrid
