#include "real_dev_meshes.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include "core/mesh/mesh_import.h"

namespace sagrid::bench {

namespace fs = std::filesystem;

fs::path benchDir() {
  const fs::path dir = fs::temp_directory_path() / "sagrid-features-bench";
  fs::create_directories(dir);
  return dir;
}

const std::vector<std::string> kRealDev = {"libero__basin_faucet", "libero__faucet_knob",
                                           "libero__flat_stove"};

fs::path realDevMesh(int i) {
  return fs::path(SAGRID_SOURCE_DIR) / ".." / "shared" / "data" / "real-dev" / kRealDev[i] /
         "mesh.obj";
}

// Splits every triangle into n x n (n chosen for >= 100k triangles) and writes an OBJ with the
// surface albedo as vertex colours, so the big mesh looks like the original.
fs::path denseCopy(int i) {
  static std::map<int, fs::path> done;
  if (done.count(i)) return done[i];
  const sagrid::Mesh mesh = sagrid::importMesh(realDevMesh(i));
  const int n = static_cast<int>(std::ceil(std::sqrt(100000.0 / mesh.triangleCount())));
  const fs::path path = benchDir() / (kRealDev[i] + "_dense.obj");
  std::ofstream out(path);
  std::size_t vertices = 0, triangles = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3f a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                          c = mesh.positions[tri[2]];
    auto index = [&](int r, int s) {
      return vertices + 1 + static_cast<std::size_t>(r * (r + 1) / 2 + s);
    };
    for (int r = 0; r <= n; ++r) {
      for (int s = 0; s <= r; ++s) {
        const float u = static_cast<float>(r - s) / n, v = static_cast<float>(s) / n;
        const Eigen::Vector3f p = a + u * (b - a) + v * (c - a);
        const Eigen::Vector3f col = mesh.albedo(static_cast<int>(t), u, v);
        out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << col.x() << ' ' << col.y()
            << ' ' << col.z() << '\n';
      }
    }
    for (int r = 0; r < n; ++r) {
      for (int s = 0; s <= r; ++s) {
        out << "f " << index(r, s) << ' ' << index(r + 1, s) << ' ' << index(r + 1, s + 1) << '\n';
        ++triangles;
        if (s < r) {
          out << "f " << index(r, s) << ' ' << index(r + 1, s + 1) << ' ' << index(r, s + 1)
              << '\n';
          ++triangles;
        }
      }
    }
    vertices += static_cast<std::size_t>((n + 1) * (n + 2) / 2);
  }
  std::fprintf(stderr, "%s: %zu triangles\n", path.c_str(), triangles);
  return done[i] = path;
}

}  // namespace sagrid::bench
