#include "core/mesh/size_measures.h"

#include <cmath>
#include <map>

#include "core/common/error.h"
#include "core/mesh/mesh.h"

namespace sagrid {

namespace {
constexpr double kHorizontalCosine = 0.9;  // |normal . z| of a face taken as horizontal
constexpr double kBaseShare = 0.1;         // faces this low (share of the height) are a base
constexpr double kBinShare = 0.02;         // height bins, share of the height

// Each measure's file name, words and member, in kSizeMeasures order.
struct MeasureEntry {
  const char* name;
  const char* words;
  double SizeMeasures::*member;
};
constexpr MeasureEntry kEntries[] = {
    {"largest_extent", "largest extent", &SizeMeasures::largestExtent},
    {"height", "height", &SizeMeasures::height},
    {"work_surface", "work surface height", &SizeMeasures::workSurface},
};
const MeasureEntry& entry(SizeMeasure measure) { return kEntries[int(measure)]; }
}  // namespace

const char* sizeMeasureName(SizeMeasure measure) { return entry(measure).name; }

SizeMeasure sizeMeasureNamed(const std::string& name) {
  for (const SizeMeasure m : kSizeMeasures)
    if (name == sizeMeasureName(m)) return m;
  throw InvalidArgument("unknown size measure '" + name +
                        "' (largest_extent, height or work_surface)");
}

const char* sizeMeasureWords(SizeMeasure measure) { return entry(measure).words; }

double SizeMeasures::operator[](SizeMeasure measure) const { return this->*entry(measure).member; }

double& SizeMeasures::operator[](SizeMeasure measure) { return this->*entry(measure).member; }

SizeMeasures measureSizes(const Mesh& mesh) {
  SizeMeasures sizes;
  if (mesh.positions.empty() || mesh.triangles.empty()) return sizes;
  const auto box = mesh.bounds();
  sizes.largestExtent = box.sizes().maxCoeff();
  sizes.height = box.sizes().z();
  if (!(sizes.height > 0)) return sizes;
  const double bottom = box.min().z(), bin = kBinShare * sizes.height;
  std::map<long, std::pair<double, double>> bins;  // bin -> (area, area-weighted height)
  const int n = int(mesh.positions.size());
  for (const auto& t : mesh.triangles) {
    if (t.minCoeff() < 0 || t.maxCoeff() >= n) continue;
    const Eigen::Vector3d a = mesh.positions[t[0]].cast<double>(), b = mesh.positions[t[1]].cast<double>(),
                          c = mesh.positions[t[2]].cast<double>();
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    const double twiceArea = cross.norm();
    if (!(twiceArea > 0) || std::abs(cross.z()) < kHorizontalCosine * twiceArea) continue;
    const double h = (a.z() + b.z() + c.z()) / 3.0 - bottom;
    if (!(h >= kBaseShare * sizes.height)) continue;
    auto& [area, weighted] = bins[long(std::floor(h / bin))];
    area += 0.5 * twiceArea;
    weighted += 0.5 * twiceArea * h;
  }
  double most = 0;
  for (const auto& [index, value] : bins)
    if (value.first > most) {
      most = value.first;
      sizes.workSurface = value.second / value.first;
    }
  return sizes;
}

}  // namespace sagrid
