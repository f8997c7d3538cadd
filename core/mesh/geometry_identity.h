// Whether two meshes are one object's geometry: two files whose triangles lie in the same places
// are the same object to a curator (colour variants of a library's model, the same washbasin with
// another material), whatever their materials, colours, textures, UVs, file format or where the
// object lies in its file. The GUI carries a curated object's points to its same-geometry twins
// (ui/app/session_twin.cpp); `sagrid info A --same-geometry-as B` says whether two files are.
//
// Two steps, so the usual open costs nothing more than one pass over the mesh:
//   - `GeometryOutline`: triangle count and box size in the file's frame, four numbers the
//     review queue keeps per object. Outlines within the tolerance make
//     a candidate (`sameOutline`); any match implies it.
//   - `matchGeometry`: the candidate's triangles against the object's, each within the tolerance
//     of one of the other's (the same corners, the same winding, from any first corner), both
//     ways, corners taken from each mesh's own box origin, so a copy placed elsewhere matches and
//     its points move by the origins' offset. A scaled, rotated or mirrored copy does not (labels
//     are in the file's frame: a twin's points carry by a translation alone).
// Tolerant, not exact: files that print coordinates to a few decimals after moving the model
// (Sweet Home 3D's LucaPresidente washbasins: 4 decimals, coordinates up to 1e-4 apart) are still
// twins, where rounding to a hash's cells split them.
#pragma once

#include <cstddef>
#include <optional>

#include "core/mesh/mesh.h"

namespace sagrid {

// The default tolerance, relative to the object's largest extent, per coordinate. Far above the
// noise of re-encoding: 4-decimal printing is 1e-4 units per coordinate (plus as much in the box
// origin) on the ~101-unit washbasins, 2e-6 relative; a float's step at 240 units, 1.5e-5, is
// 1.5e-5 of a 1-unit object placed that far. Far below an edit a curator would see: 1 mm on a 1 m
// stove is 1e-3, a knob moved by its own size 1e-2.
inline constexpr double kSameGeometryTolerance = 1e-4;

struct GeometryOutline {
  std::size_t triangles = 0;
  // The size of the triangles' box in the file's frame and units (not where it lies: a copy
  // placed elsewhere has the same outline).
  Eigen::Vector3d size = Eigen::Vector3d::Zero();

  double extent() const { return size.maxCoeff(); }
  bool operator==(const GeometryOutline& other) const {
    return triangles == other.triangles && size == other.size;
  }
};

// Nullopt for a mesh with no triangle or no extent (nothing to be the same as: two failed or
// empty imports are not twins). Throws InvalidArgument for a triangle naming a vertex the mesh
// lacks or a position that is not finite.
std::optional<GeometryOutline> geometryOutline(const Mesh& mesh);

// Equal triangle counts and box sizes within relativeTolerance of the larger extent: a candidate.
bool sameOutline(const GeometryOutline& a, const GeometryOutline& b,
                 double relativeTolerance = kSameGeometryTolerance);

struct GeometryMatch {
  // What moves `from`'s label coordinates (file frame) onto `to`: the lowest corner of `to`'s
  // box less `from`'s.
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  // Triangle i of one is triangle i of the other: triangle indices (a control's part in
  // labels.json) mean the same faces in both.
  bool sameTriangleOrder = false;
};

// Whether `to` is `from`'s triangles up to a translation, each corner within relativeTolerance x
// the larger extent (per coordinate) of the other's, relative to each box's origin. O(n): the
// triangles are looked up in a hashed grid of cells the tolerance's size by their centre. Nullopt
// for no match or a mesh without outline. Throws InvalidArgument as geometryOutline does, and for
// a tolerance outside (0, 1).
std::optional<GeometryMatch> matchGeometry(const Mesh& from, const Mesh& to,
                                           double relativeTolerance = kSameGeometryTolerance);

}  // namespace sagrid
