// A small procedural modelling kit: primitives (rounded boxes, surfaces of revolution, swept
// tubes, lofted rounded rectangles, plates with a rounded hole) placed by transforms into one
// merged Mesh with per-part materials. Generators of stoves and sinks are built on it.
// Units are metres, z up. Primitives do not share vertices, so each stays watertight on its own
// and the merged mesh looks like a downloaded asset (one soup, no part names).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/mesh/mesh.h"

namespace sagrid::gen {

using Vec2 = Eigen::Vector2f;
using Vec3 = Eigen::Vector3f;
using Affine = Eigen::Affine3f;

Affine translation(const Vec3& t);
Affine translation(float x, float y, float z);
Affine rotationZ(float radians);
Affine rotationX(float radians);
Affine rotationY(float radians);
// A frame whose local z axis points along `axis` (any roll), placed at `origin`.
Affine alignZTo(const Vec3& origin, const Vec3& axis);

// A rectangle with rounded corners in a plane of constant z (a ring of a loft).
struct RoundedRect {
  Vec2 center{0, 0};
  Vec2 half{0.1f, 0.1f};  // half extents
  float radius = 0;       // corner radius, <= min(half)
  float z = 0;
};

class ShapeBuilder {
 public:
  ShapeBuilder();

  // Materials are deduplicated by name.
  int material(const std::string& name, const Vec3& color, int texture = -1);
  int addTexture(Texture texture);

  // Box of the given full size centred at the local origin; edges rounded with `bevel`
  // (0 = sharp) in `bevelSegments` steps; faces split `subdivisions` times per axis.
  void box(const Affine& xf, const Vec3& size, int material, float bevel = 0,
           int bevelSegments = 2, int subdivisions = 1);
  // Axis-aligned box from min to max corner (object frame), sharp.
  void boxFromTo(const Vec3& lo, const Vec3& hi, int material, int subdivisions = 1);

  // Surface of revolution about local z of a profile of (radius, z) points, from bottom to top.
  // Profile ends with radius 0 close the solid. Each profile segment is its own band (crisp
  // creases between segments).
  void lathe(const Affine& xf, const std::vector<Vec2>& profile, int segments, int material);
  // Closed cylinder along local z from z0 to z1.
  void cylinder(const Affine& xf, float radius, float z0, float z1, int segments, int material);

  // A circle of `radius` swept along a polyline (object frame), parallel-transport frames.
  void tube(const std::vector<Vec3>& path, float radius, int sides, int material,
            bool capStart = true, bool capEnd = true);

  // Lofts through rounded rectangles (same sampling each), local frame. Rings go bottom to top
  // for an outside surface and top to bottom for a cavity; caps are fans at the ring centre.
  void loft(const Affine& xf, const std::vector<RoundedRect>& rings, int cornerSegments,
            int material, bool capFirst, bool capLast);

  // A slab from z0 to z1 covering [-outerHalf, outerHalf] with a rounded rectangular hole
  // (hole.z ignored): counter tops and sink decks.
  void plateWithHole(const Affine& xf, const Vec2& outerHalf, const RoundedRect& hole, float z0,
                     float z1, int cornerSegments, int material);

  // A flat rectangle facing local +z with UVs spanning [0,1]^2 over it (for painted textures).
  void texturedQuad(const Affine& xf, const Vec2& size, int material, int subdivisions = 1);

  std::size_t vertexCount() const { return m_mesh.positions.size(); }
  std::size_t triangleCount() const { return m_mesh.triangles.size(); }

  // Finishes the mesh: vertex normals, and UVs dropped when no texture is used.
  Mesh build() &&;

 private:
  int addVertex(const Vec3& p, const Vec2& uv = Vec2::Zero());
  void addTriangle(int a, int b, int c, int material);
  void addQuad(int a, int b, int c, int d, int material);  // a-b-c-d counter-clockwise
  std::vector<Vec2> sampleRoundedRect(const RoundedRect& rect, int cornerSegments) const;

  Mesh m_mesh;
};

}  // namespace sagrid::gen
