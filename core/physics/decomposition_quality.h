// How well a set of convex parts stands in for a mesh, as the decomposition benchmark reports it
// for ours and V-HACD alike.
//
// Concavity (the measure of CoACD, Wei et al. 2022, applied to the whole decomposition): the
// largest distance from a point of the surface of the union of the hulls that lies outside the
// mesh to the mesh surface -- the one-sided Hausdorff distance from the part of the union's
// boundary that sticks out of the object to the object's surface, which is CoACD's
// h(boundary of CH(P), boundary of P) since a hull contains its part. The union's surface is
// sampled by covering every hull's triangles with points at most `spacing` apart and dropping
// those strictly inside another hull; a point is outside the mesh when its voxel (IoU grid) is
// outside the filled solid, or is a surface voxel and the point lies in front of its nearest
// triangle (outward winding by the sign of the signed volume); distances are exact
// (Embree closest point). A hull that spans a cavity scores the cavity's depth; points of the
// union's boundary inside the solid (parts that do not quite meet) and parts that miss geometry
// are not concavity: the IoU catches them.
//
// Volume IoU: on a voxel grid over the mesh's box, the voxels of the mesh's solid (the filled
// surface of solid_voxels.h: enclosed voxels, plus surface voxels whose centre lies inside the
// surface) against the voxels whose centre lies in some hull; |A and B| / |A or B|.
#pragma once

#include <vector>

#include "core/physics/convex_part.h"

namespace sagrid {

struct Mesh;

namespace physics {

struct DecompositionQuality {
  double concavity = 0;          // mesh units
  double relativeConcavity = 0;  // concavity / the mesh's bounding-box diagonal
  double volumeIoU = 0;
  double hullVolume = 0;         // sum of the parts' volumes, mesh units^3
};

// `spacing` is a fraction of the bounding-box diagonal; `resolution` the IoU grid.
DecompositionQuality measureDecomposition(const Mesh& mesh, const std::vector<ConvexPart>& parts,
                                          double spacing = 0.005, int resolution = 128);

}  // namespace physics
}  // namespace sagrid
