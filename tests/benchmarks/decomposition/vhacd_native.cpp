// Runs V-HACD 4 natively (VHACD.h from the vhacd-js package, single-threaded like the WASM
// build) on every WORK/<name>/input.obj; writes vhacd_native.obj and vhacd_native.time.
// Built by run.sh against the fetched header (the header is not kept in this repository).
// usage: vhacd_native WORK MAX_HULLS
#define ENABLE_VHACD_IMPLEMENTATION 1
#define VHACD_DISABLE_THREADING 1
#include "VHACD.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: vhacd_native WORK MAX_HULLS\n";
    return 2;
  }
  for (const auto& entry : fs::directory_iterator(argv[1])) {
    const fs::path input = entry.path() / "input.obj";
    if (!fs::exists(input)) continue;
    std::vector<double> points;
    std::vector<uint32_t> triangles;
    std::ifstream in(input);
    std::string line;
    while (std::getline(in, line)) {
      std::istringstream s(line);
      std::string tag;
      s >> tag;
      if (tag == "v") {
        double x, y, z;
        s >> x >> y >> z;
        points.insert(points.end(), {x, y, z});
      } else if (tag == "f") {
        uint32_t a, b, c;
        s >> a >> b >> c;
        triangles.insert(triangles.end(), {a - 1, b - 1, c - 1});
      }
    }
    VHACD::IVHACD::Parameters parameters;
    parameters.m_maxConvexHulls = static_cast<uint32_t>(std::stoi(argv[2]));
    parameters.m_asyncACD = false;
    VHACD::IVHACD* vhacd = VHACD::CreateVHACD();
    const auto start = std::chrono::steady_clock::now();
    vhacd->Compute(points.data(), static_cast<uint32_t>(points.size() / 3), triangles.data(),
                   static_cast<uint32_t>(triangles.size() / 3), parameters);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::ofstream out(entry.path() / "vhacd_native.obj");
    std::size_t base = 1;
    for (uint32_t h = 0; h < vhacd->GetNConvexHulls(); ++h) {
      VHACD::IVHACD::ConvexHull hull;
      vhacd->GetConvexHull(h, hull);
      out << "o hull_" << h << "\n";
      for (const auto& p : hull.m_points) out << "v " << p.mX << " " << p.mY << " " << p.mZ << "\n";
      for (const auto& t : hull.m_triangles)
        out << "f " << t.mI0 + base << " " << t.mI1 + base << " " << t.mI2 + base << "\n";
      base += hull.m_points.size();
    }
    std::ofstream(entry.path() / "vhacd_native.time") << seconds << "\n";
    std::cout << entry.path().filename().string() << ": V-HACD native " << vhacd->GetNConvexHulls()
              << " hulls, " << seconds << " s\n";
    vhacd->Release();
  }
  return 0;
}
