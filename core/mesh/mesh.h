// The triangle mesh every stage of SAGrid works on: all nodes of a file merged into one mesh in
// the file's frame turned z-up, with what is needed to sample a surface albedo later
// (per-vertex colour, per-triangle material, material base colour and texture with UVs).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sagrid {

// An RGBA8 image, rows top to bottom, as decoded from a texture file or an embedded image.
struct Texture {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4

  // Linear RGB in [0,1], bilinear, UV wrapping with repeat; v=0 is the bottom row (OpenGL/OBJ).
  Eigen::Vector3f sample(const Eigen::Vector2f& uv) const;
};

struct Material {
  std::string name;
  Eigen::Vector3f baseColor{1.0f, 1.0f, 1.0f};  // multiplies texture and vertex colour
  int texture = -1;                              // index into Mesh::textures, or -1
};

enum class UpAxis { Y, Z };

struct Mesh {
  std::vector<Eigen::Vector3f> positions;  // z-up frame (after any up-axis conversion)
  std::vector<Eigen::Vector3f> normals;    // per vertex, unit length; same size as positions
  std::vector<Eigen::Vector2f> uvs;        // per vertex, or empty
  std::vector<Eigen::Vector3f> colors;     // per vertex RGB in [0,1], or empty (= white)
  std::vector<Eigen::Vector3i> triangles;
  std::vector<int> triangleMaterials;      // per triangle index into materials, or empty
  std::vector<Material> materials;
  std::vector<Texture> textures;

  UpAxis fileUp = UpAxis::Z;  // the up axis of the source file (labels are written in it)
  std::string sha256;         // of the source file's bytes; empty for generated meshes

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }
  Eigen::AlignedBox3f bounds() const;

  // Albedo at a point of triangle `tri` with barycentrics (u, v) (Embree convention:
  // p = (1-u-v) * v0 + u * v1 + v * v2).
  Eigen::Vector3f albedo(int tri, float u, float v) const;

  // Recomputes area-weighted per-vertex normals from the triangles.
  void computeVertexNormals();
};

// Converts between the file's frame and SAGrid's z-up frame. A y-up file (glTF) maps
// (x, y, z)_file -> (x, -z, y)_zup, a rotation of +90 degrees about x.
Eigen::Vector3f fileToZUp(const Eigen::Vector3f& p, UpAxis fileUp);
Eigen::Vector3f zUpToFile(const Eigen::Vector3f& p, UpAxis fileUp);

}  // namespace sagrid
