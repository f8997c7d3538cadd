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

// The file axis that points up. Y and Z name +y and +z (glTF's and SAGrid's own up axes).
enum class UpAxis { PosX, NegX, PosY, NegY, PosZ, NegZ, Y = PosY, Z = PosZ };

// The six axes in enum order, for loops over candidates.
constexpr UpAxis kAllUpAxes[] = {UpAxis::PosX, UpAxis::NegX, UpAxis::PosY,
                                 UpAxis::NegY, UpAxis::PosZ, UpAxis::NegZ};

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
  // How sure the up axis is: 1 when given (--up, labels) or fixed by the format. With
  // fileUpDetected (the geometry was looked at, ImportOptions::detectUp): the detection's
  // confidence when its axis was taken, or the kept default's softmax probability when the
  // detection was too unsure to turn the file.
  float fileUpConfidence = 1.0f;
  bool fileUpDetected = false;
  std::string sha256;         // of the source file's bytes; empty for generated meshes

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }
  Eigen::AlignedBox3f bounds() const;

  // Albedo at a point of triangle `tri` with barycentrics (u, v) (Embree convention:
  // p = (1-u-v) * v0 + u * v1 + v * v2).
  Eigen::Vector3f albedo(int tri, float u, float v) const;

  // Recomputes area-weighted per-vertex normals from the triangles.
  void computeVertexNormals();

  // Adds `part`'s triangles, vertices, materials and textures after this mesh's own (indices
  // shifted; a per-vertex attribute only one side has is filled with white colours or zero UVs).
  // Frames must already agree: fileUp and the other file bookkeeping stay this mesh's.
  void append(const Mesh& part);

  // Its materials, textures and file-frame bookkeeping without vertices, triangles or sha256:
  // the start of a mesh cut from this one (a crop, a subset of its triangles).
  Mesh withoutGeometry() const;
};

// The area of each triangle (0 for one with a corner the mesh lacks).
std::vector<float> triangleAreas(const Mesh& mesh);

// Converts between the file's frame and SAGrid's z-up frame with a proper rotation (det +1) that
// takes the file's up axis to +z. A y-up file (glTF) maps (x, y, z)_file -> (x, -z, y)_zup, a
// rotation of +90 degrees about x; -y: -90 about x; +x: -90 about y; -x: +90 about y; -z: 180
// about x. The entries are 0/+-1, so conversions are exact.
Eigen::Matrix3f fileToZUpRotation(UpAxis fileUp);
// The unit vector of `up` in the file's frame (e.g. NegY -> (0,-1,0)).
Eigen::Vector3f upAxisVector(UpAxis up);
Eigen::Vector3f fileToZUp(const Eigen::Vector3f& p, UpAxis fileUp);
Eigen::Vector3f zUpToFile(const Eigen::Vector3f& p, UpAxis fileUp);

}  // namespace sagrid
