#include "core/export/stl_file.h"

#include <cstdint>
#include <cstring>

#include "core/common/error.h"
#include "core/io/little_endian.h"

namespace sagrid::exportdetail {

std::string encodeBinaryStl(const Mesh& mesh) {
  std::string out(80, '\0');
  std::memcpy(out.data(), "binary STL written by sagrid", 28);
  out.reserve(84 + mesh.triangles.size() * 50);
  io::put32(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  auto appendVector = [&out](const Eigen::Vector3f& v) {
    for (int i = 0; i < 3; ++i) {
      std::uint32_t bits;
      std::memcpy(&bits, &v[i], 4);
      io::put32(out, bits);
    }
  };
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3f& a = mesh.positions[t[0]];
    const Eigen::Vector3f& b = mesh.positions[t[1]];
    const Eigen::Vector3f& c = mesh.positions[t[2]];
    if (!a.allFinite() || !b.allFinite() || !c.allFinite())
      throw Error("internal error: a non-finite vertex reached the STL writer");
    Eigen::Vector3f n = (b - a).cross(c - a);
    const float length = n.norm();
    n = length > 0.0f ? Eigen::Vector3f(n / length) : Eigen::Vector3f::Zero();
    appendVector(n);
    appendVector(a);
    appendVector(b);
    appendVector(c);
    out.append(2, '\0');
  }
  return out;
}

}  // namespace sagrid::exportdetail
