// The identity of a mesh's geometry alone: two files whose triangles lie in the same places are
// the same object to a curator (colour variants of a library's model, the same washbasin with
// another material), whatever their materials, colours, textures, UVs or file format. The GUI
// carries a curated object's points to its same-geometry twins (ui/app/session_twin.cpp);
// `sagrid info --geometry-id` prints it.
//
// What it hashes: every triangle as the three corners' positions in the mesh file's own frame
// taken from the lowest corner of the triangles' box, so the same triangles moved elsewhere in
// the file (a library placing each variant at its own spot of a scene) are the same identity,
// while a scaled, rotated or mirrored copy is another (the same triangles written in another
// frame, a z-up OBJ of a y-up GLB, are a rotated copy: labels are in the file's frame, so a twin's
// points carry by a translation alone). Each coordinate is rounded to a cell of 2^-14 of the
// object's largest extent (rounded up to a power of two, so the cell itself does not move with
// float noise in the extent): 0.06 mm on a 1 m stove. `origin` keeps where the box begins, so a
// twin's points move onto this copy by the difference of the two origins.
//   - `shape` ignores the order of vertices and triangles and how vertices are shared or split
//     (exporters split vertices at UV seams and group triangles by material, so neither is part
//     of the geometry): each triangle starts at its smallest corner (keeping its winding) and the
//     triangles are sorted.
//   - `triangleOrder` also keeps the triangles' order: where it agrees, triangle indices (a
//     control's part in labels.json) mean the same faces in both meshes.
// Rounding absorbs the noise of re-encoding only where a coordinate does not straddle a cell
// boundary, so exporters that jitter many coordinates can hide a twin; the error goes the safe way
// (a missed twin is reviewed as usual, never a wrong one carried).
#pragma once

#include <optional>
#include <string>

#include "core/mesh/mesh.h"

namespace sagrid {

struct GeometryIdentity {
  std::string shape;          // 32 hex digits (sha256 prefix)
  std::string triangleOrder;  // 32 hex digits
  // The lowest corner of the triangles' box in the file's frame and units: where this copy lies,
  // not part of the shape (twins are found by `shape` alone).
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();

  bool operator==(const GeometryIdentity& other) const {
    return shape == other.shape && triangleOrder == other.triangleOrder && origin == other.origin;
  }
};

// What moves a twin's label coordinates (file frame) onto `to`: to.origin - from.origin.
Eigen::Vector3d twinOffset(const GeometryIdentity& from, const GeometryIdentity& to);

// Nullopt for a mesh with no triangle or no extent (nothing to be identical to: two failed or
// empty imports are not twins). Throws InvalidArgument for a triangle naming a vertex the mesh
// lacks or a position that is not finite.
std::optional<GeometryIdentity> geometryIdentity(const Mesh& mesh);

}  // namespace sagrid
