#include "core/features/texture_detail.h"

#include <algorithm>
#include <cmath>

#include "core/features/surface_samples.h"
#include "core/mesh/mesh.h"

namespace sagrid {

namespace {

float luminance(const Eigen::Vector3f& rgb) {
  return 0.2126f * rgb.x() + 0.7152f * rgb.y() + 0.0722f * rgb.z();
}

struct Accumulator {
  double weight = 0, sum = 0, squares = 0;  // luminance moments, area-weighted
  double edgeWeight = 0, edges = 0;         // mean neighbour step, area-weighted
};

}  // namespace

std::vector<std::string> textureDetailChannelNames() {
  return {"texture_variation", "texture_edges"};
}

std::vector<float> textureDetail(const Mesh& mesh, const VoxelGrid& grid, int lattice) {
  const int n = std::max(1, lattice);
  std::vector<Accumulator> acc(grid.occupiedCount());
  std::vector<float> lum(static_cast<std::size_t>(n * n));
  forEachSurfacePiece(mesh, grid, [&](const SurfacePiece& piece) {
    Accumulator& a = acc[static_cast<std::size_t>(piece.slot)];
    const Eigen::Vector3f& p0 = piece.vertices[0];
    for (int f = 1; f + 1 < piece.vertexCount; ++f) {
      const Eigen::Vector3f e1 = piece.vertices[f] - p0, e2 = piece.vertices[f + 1] - p0;
      const double area = 0.5 * e1.cross(e2).norm();
      if (!(area > 0)) continue;
      // Lattice points (i + 1/3, j + 1/3) / n with i + j < n: the centroids of the lattice's
      // upright sub-triangles, all inside the fan triangle.
      int samples = 0;
      for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
          const Eigen::Vector3f q = p0 + ((i + 1.0f / 3) / n) * e1 + ((j + 1.0f / 3) / n) * e2;
          const Eigen::Vector2f uv = barycentricIn(mesh, piece.triangle, q);
          lum[static_cast<std::size_t>(i * n + j)] =
              luminance(mesh.albedo(piece.triangle, uv.x(), uv.y()));
          ++samples;
        }
      double steps = 0;
      int pairs = 0;
      for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
          const float l = lum[static_cast<std::size_t>(i * n + j)];
          a.sum += area / samples * l;
          a.squares += area / samples * l * l;
          if (i + 1 + j < n) {
            steps += std::abs(lum[static_cast<std::size_t>((i + 1) * n + j)] - l);
            steps += std::abs(lum[static_cast<std::size_t>(i * n + j + 1)] - l);
            pairs += 2;
          }
        }
      a.weight += area;
      if (pairs > 0) {
        a.edges += area * steps / pairs;
        a.edgeWeight += area;
      }
    }
  });
  std::vector<float> out(acc.size() * kTextureDetailChannels, 0.0f);
  for (std::size_t p = 0; p < acc.size(); ++p) {
    const Accumulator& a = acc[p];
    if (a.weight <= 0) continue;
    const double mean = a.sum / a.weight;
    const double variance = std::max(0.0, a.squares / a.weight - mean * mean);
    out[p * kTextureDetailChannels] = std::min(1.0f, static_cast<float>(2 * std::sqrt(variance)));
    if (a.edgeWeight > 0)
      out[p * kTextureDetailChannels + 1] =
          std::min(1.0f, static_cast<float>(4 * a.edges / a.edgeWeight));
  }
  return out;
}

}  // namespace sagrid
