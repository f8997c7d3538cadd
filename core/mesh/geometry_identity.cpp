#include "core/mesh/geometry_identity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/common/error.h"
#include "core/common/sha256.h"

namespace sagrid {

namespace {

constexpr int kCellsPerExtentLog2 = 14;
constexpr std::size_t kHexDigits = 32;

using Corner = std::array<std::int32_t, 3>;  // cells from the lowest corner of the box
using CellTriangle = std::array<Corner, 3>;  // starting at its smallest corner, winding kept

CellTriangle startAtSmallestCorner(const CellTriangle& t) {
  const std::size_t first =
      static_cast<std::size_t>(std::min_element(t.begin(), t.end()) - t.begin());
  return {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
}

std::string hashOf(const std::string& header, const std::vector<CellTriangle>& triangles) {
  std::string bytes = header;
  bytes.append(reinterpret_cast<const char*>(triangles.data()),
               triangles.size() * sizeof(CellTriangle));
  return sha256Hex(bytes).substr(0, kHexDigits);
}

}  // namespace

Eigen::Vector3d twinOffset(const GeometryIdentity& from, const GeometryIdentity& to) {
  return to.origin - from.origin;
}

std::optional<GeometryIdentity> geometryIdentity(const Mesh& mesh) {
  if (mesh.triangles.empty()) return std::nullopt;
  const int vertexCount = static_cast<int>(mesh.positions.size());
  std::vector<Eigen::Vector3d> file(mesh.positions.size());
  for (std::size_t v = 0; v < file.size(); ++v)
    file[v] = zUpToFile(mesh.positions[v], mesh.fileUp).cast<double>();

  // The box of the triangles' corners (a stray vertex no triangle uses is not geometry).
  Eigen::AlignedBox3d box;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      if (v < 0 || v >= vertexCount)
        throw InvalidArgument("geometry identity: triangle " + std::to_string(t) +
                              " names vertex " + std::to_string(v) + " of a mesh with " +
                              std::to_string(vertexCount));
      if (!file[std::size_t(v)].allFinite())
        throw InvalidArgument("geometry identity: vertex " + std::to_string(v) + " is not finite");
      box.extend(file[std::size_t(v)]);
    }
  }
  const double extent = box.sizes().maxCoeff();
  if (!(extent > 0)) return std::nullopt;

  // A power-of-two cell: (x - lowest) / cell is exact (the difference of two floats is a double),
  // so rounding depends on where the corner lies in the box alone, not where the box lies.
  const int exponent = static_cast<int>(std::ceil(std::log2(extent))) - kCellsPerExtentLog2;
  auto cornerOf = [&](int v) {
    Corner c{};
    for (int a = 0; a < 3; ++a)
      c[std::size_t(a)] = static_cast<std::int32_t>(
          std::llround(std::ldexp(file[std::size_t(v)][a] - box.min()[a], -exponent)));
    return c;
  };

  std::vector<CellTriangle> inOrder;
  inOrder.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& t : mesh.triangles)
    inOrder.push_back(startAtSmallestCorner({cornerOf(t[0]), cornerOf(t[1]), cornerOf(t[2])}));

  // The cell size, so a copy scaled by a power of two (the same cells) differs.
  const std::string header(reinterpret_cast<const char*>(&exponent), sizeof exponent);

  GeometryIdentity identity;
  identity.triangleOrder = hashOf(header, inOrder);
  std::sort(inOrder.begin(), inOrder.end());
  identity.shape = hashOf(header, inOrder);
  identity.origin = box.min();
  return identity;
}

}  // namespace sagrid
