// Convex decomposition benchmark: ours against V-HACD 4 on the same meshes, one table.
//
//   decomposition_compare prepare  WORK MESH...   writes WORK/<name>/input.obj (z-up, as imported)
//   decomposition_compare parts-glb OBJ OUT.glb    writes the hulls of OBJ (ours.obj, ...) as one
//       GLB, each part in its own colour, for `sagrid render` (pictures of the collision parts)
//   decomposition_compare evaluate WORK           runs ours on every WORK/<name>/input.obj, reads
//       the hulls V-HACD wrote beside it (vhacd_wasm.obj, vhacd_native.obj: one `o` group per
//       hull) with their times (*.time: seconds), measures all (decomposition_quality.h) and
//       prints a Markdown table per object plus medians.
// run.sh drives the whole comparison (fetches vhacd-js, runs V-HACD under node and natively).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_import.h"
#include "core/physics/convex_decomposition.h"
#include "core/physics/decomposition_quality.h"

namespace fs = std::filesystem;
using namespace sagrid;

namespace {

void writeObj(const fs::path& path, const std::vector<const Mesh*>& groups) {
  std::ofstream out(path);
  std::size_t base = 1;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    out << "o part_" << g << "\n";
    for (const auto& p : groups[g]->positions) out << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
    for (const auto& t : groups[g]->triangles)
      out << "f " << t[0] + base << " " << t[1] + base << " " << t[2] + base << "\n";
    base += groups[g]->positions.size();
  }
}

// One ConvexPart per `o` group of a plain OBJ (v and f lines only, as our writers write).
std::vector<physics::ConvexPart> readHulls(const fs::path& path) {
  std::vector<physics::ConvexPart> parts;
  std::vector<Eigen::Vector3f> all;
  std::ifstream in(path);
  std::string line;
  std::size_t groupStart = 0;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "o") {
      parts.emplace_back();
      groupStart = all.size();
    } else if (tag == "v") {
      Eigen::Vector3f v;
      s >> v.x() >> v.y() >> v.z();
      all.push_back(v);
      if (parts.empty()) parts.emplace_back();
      parts.back().vertices.push_back(v);
    } else if (tag == "f") {
      Eigen::Vector3i t;
      s >> t[0] >> t[1] >> t[2];
      parts.back().triangles.push_back(t - Eigen::Vector3i::Constant(static_cast<int>(groupStart) + 1));
    }
  }
  // V-HACD's winding may face inwards; orient every hull outwards so point tests work.
  for (auto& p : parts)
    if (p.volume() < 0)
      for (auto& t : p.triangles) std::swap(t[1], t[2]);
  return parts;
}

double readSeconds(const fs::path& path) {
  std::ifstream in(path);
  double s = -1;
  in >> s;
  return s;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

struct Row {
  std::size_t parts = 0;
  physics::DecompositionQuality quality;
  double seconds = 0;
};

int prepare(const fs::path& work, const std::vector<std::string>& meshes) {
  for (const auto& m : meshes) {
    const fs::path path(m);
    const Mesh mesh = importMesh(path);
    std::string name = path.parent_path().filename().string() + "__" + path.stem().string();
    fs::create_directories(work / name);
    writeObj(work / name / "input.obj", {&mesh});
    std::cout << name << ": " << mesh.triangleCount() << " triangles\n";
  }
  return 0;
}

// Parts as one mesh, a colour per part (hues around the wheel), flat-shaded.
int partsGlb(const fs::path& obj, const fs::path& out) {
  const auto parts = readHulls(obj);
  Mesh mesh;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const float hue = std::fmod(0.618034f * static_cast<float>(p), 1.0f) * 6.0f;
    const float x = 1.0f - std::abs(std::fmod(hue, 2.0f) - 1.0f);
    const Eigen::Vector3f rgb = hue < 1 ? Eigen::Vector3f(1, x, 0) : hue < 2 ? Eigen::Vector3f(x, 1, 0)
                                : hue < 3 ? Eigen::Vector3f(0, 1, x) : hue < 4 ? Eigen::Vector3f(0, x, 1)
                                : hue < 5 ? Eigen::Vector3f(x, 0, 1) : Eigen::Vector3f(1, 0, x);
    for (const auto& t : parts[p].triangles) {
      const int base = static_cast<int>(mesh.positions.size());
      for (int c = 0; c < 3; ++c) {
        mesh.positions.push_back(parts[p].vertices[t[c]]);
        mesh.colors.push_back(0.25f * Eigen::Vector3f::Ones() + 0.75f * rgb);
      }
      mesh.triangles.emplace_back(base, base + 1, base + 2);
    }
  }
  mesh.computeVertexNormals();
  mesh.fileUp = UpAxis::Y;  // GLB is y-up by its spec: the writer turns the z-up parts
  std::ofstream(out, std::ios::binary) << encodeGlb(mesh);
  std::cout << out.string() << ": " << parts.size() << " parts\n";
  return 0;
}

int evaluate(const fs::path& work) {
  std::vector<fs::path> objects;
  for (const auto& entry : fs::directory_iterator(work))
    if (fs::exists(entry.path() / "input.obj")) objects.push_back(entry.path());
  std::sort(objects.begin(), objects.end());
  std::vector<std::string> methods{"ours", "vhacd_native", "vhacd_wasm"};
  if (std::getenv("OURS_ONLY")) methods = {"ours"};
  std::map<std::string, std::vector<Row>> rows;
  std::printf("| object | triangles | method | parts | concavity (%% of diagonal) | volume IoU | time (s) |\n");
  std::printf("| --- | ---: | --- | ---: | ---: | ---: | ---: |\n");
  for (const auto& dir : objects) {
    const Mesh mesh = importMesh(dir / "input.obj");
    for (const auto& method : methods) {
      Row row;
      std::vector<physics::ConvexPart> parts;
      if (method == "ours") {
        const auto start = std::chrono::steady_clock::now();
        physics::DecompositionOptions options;
        if (const char* r = std::getenv("OURS_RESOLUTION")) options.resolution = std::atoi(r);
        parts = physics::decomposeConvex(mesh, options).parts;
        row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::vector<Mesh> meshes;
        for (const auto& p : parts) meshes.push_back(physics::toMesh(p));
        std::vector<const Mesh*> groups;
        for (const auto& m : meshes) groups.push_back(&m);
        writeObj(dir / "ours.obj", groups);
      } else {
        if (!fs::exists(dir / (method + ".obj"))) continue;
        parts = readHulls(dir / (method + ".obj"));
        row.seconds = readSeconds(dir / (method + ".time"));
      }
      row.parts = parts.size();
      row.quality = physics::measureDecomposition(mesh, parts);
      rows[method].push_back(row);
      std::printf("| %s | %zu | %s | %zu | %.2f | %.3f | %.2f |\n", dir.filename().c_str(),
                  mesh.triangleCount(), method.c_str(), row.parts, 100 * row.quality.relativeConcavity,
                  row.quality.volumeIoU, row.seconds);
      std::fflush(stdout);
    }
  }
  std::printf("\n| method | objects | median parts | median concavity (%% of diagonal) | median volume IoU | median time (s) |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: |\n");
  for (const auto& method : methods) {
    const auto& r = rows[method];
    if (r.empty()) continue;
    std::vector<double> parts, concavity, iou, seconds;
    for (const auto& row : r) {
      parts.push_back(static_cast<double>(row.parts));
      concavity.push_back(100 * row.quality.relativeConcavity);
      iou.push_back(row.quality.volumeIoU);
      seconds.push_back(row.seconds);
    }
    std::printf("| %s | %zu | %.0f | %.2f | %.3f | %.2f |\n", method.c_str(), r.size(), median(parts),
                median(concavity), median(iou), median(seconds));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.size() >= 2 && args[0] == "prepare")
      return prepare(args[1], std::vector<std::string>(args.begin() + 2, args.end()));
    if (args.size() == 2 && args[0] == "evaluate") return evaluate(args[1]);
    if (args.size() == 3 && args[0] == "parts-glb") return partsGlb(args[1], args[2]);
    std::cerr << "usage: decomposition_compare prepare WORK MESH... | evaluate WORK | parts-glb OBJ OUT.glb\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "decomposition_compare: " << e.what() << "\n";
    return 1;
  }
}
