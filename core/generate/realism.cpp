#include "core/generate/realism.h"

#include <cmath>

#include "core/generate/angles.h"

namespace sagrid::gen {

namespace {

// Noise as a function of the (quantised) position, so coincident vertices of different parts
// move together and no cracks open.
Eigen::Vector3f positionNoise(const Eigen::Vector3f& p, std::uint64_t salt) {
  std::uint64_t h = salt;
  for (int k = 0; k < 3; ++k) {
    const auto q = static_cast<std::int64_t>(std::llround(p[k] * 1e5));
    h = deriveSeed(h, "n", static_cast<std::uint64_t>(q));
  }
  Eigen::Vector3f v;
  for (int k = 0; k < 3; ++k) {
    h = deriveSeed(h, "c", static_cast<std::uint64_t>(k));
    v[k] = static_cast<float>((h >> 11) * (1.0 / 9007199254740992.0)) * 2.0f - 1.0f;
  }
  return v;
}

}  // namespace

RealismResult applyRealism(GeneratedObject& object, Rng& rng, UpAxis fileUp) {
  RealismResult result;
  Mesh& mesh = object.mesh;
  keepPointsNearParts(mesh, object.points, kGroundTruthMaxDistance);

  // Vertex noise (metres).
  if (rng.chance(0.35)) {
    const float amplitude = rng.uniformf(0.0002, 0.001);
    const std::uint64_t salt = rng.next();
    for (auto& p : mesh.positions) p += amplitude * positionNoise(p, salt);
    result.record["noise_m"] = std::round(amplitude * 1e5f) / 1e5f;
    mesh.computeVertexNormals();
  }

  // Colour carried by vertex colours instead of materials (as many scanned/converted assets).
  if (rng.chance(0.3)) {
    mesh.colors.assign(mesh.positions.size(), Eigen::Vector3f::Ones());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const Material& m = mesh.materials[mesh.triangleMaterials[t]];
      if (m.texture >= 0) continue;
      for (int k = 0; k < 3; ++k) mesh.colors[mesh.triangles[t][k]] = m.baseColor;
    }
    for (auto& m : mesh.materials) {
      if (m.texture < 0) m.baseColor = Eigen::Vector3f::Ones();
    }
    result.record["colors"] = "vertex";
  } else {
    result.record["colors"] = "material";
  }

  // Whole-object yaw and origin.
  float yaw = 0;
  const int yawMode = rng.weighted({0.2, 0.35, 0.45});
  if (yawMode == 1) yaw = 0.5f * kPi * rng.uniformInt(1, 3);
  else if (yawMode == 2) yaw = rng.uniformf(0, 2 * kPi);
  const Eigen::Matrix3f rotation = Eigen::AngleAxisf(yaw, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  const Eigen::AlignedBox3f box = mesh.bounds();
  Eigen::Vector3f origin = Eigen::Vector3f::Zero();  // as built: floor centre
  const int originMode = rng.weighted({0.4, 0.35, 0.25});
  if (originMode == 1) origin = box.center();
  else if (originMode == 2) {
    origin = box.center() + box.sizes().cwiseProduct(Eigen::Vector3f(rng.uniformf(-0.5, 0.5), rng.uniformf(-0.5, 0.5),
                                                                      rng.uniformf(-0.5, 0.5)));
  }
  result.record["yaw_deg"] = std::round(yaw * 180.0f / kPi * 10.0f) / 10.0f;
  result.record["origin"] = originMode == 0 ? "base" : originMode == 1 ? "center" : "offset";

  // Units.
  const int unitMode = rng.weighted({0.5, 0.2, 0.2, 0.1});
  static const char* kUnits[] = {"m", "cm", "mm", "in"};
  static const double kMetersPerUnit[] = {1.0, 0.01, 0.001, 0.0254};
  result.units = kUnits[unitMode];
  result.metersPerUnit = kMetersPerUnit[unitMode];
  const float scale = static_cast<float>(1.0 / result.metersPerUnit);

  for (auto& p : mesh.positions) p = scale * (rotation * (p - origin));
  for (auto& n : mesh.normals) n = rotation * n;
  for (auto& g : object.points) {
    g.position = scale * (rotation * (g.position - origin));
    g.normal = rotation * g.normal;
  }
  mesh.fileUp = fileUp;
  return result;
}

}  // namespace sagrid::gen
