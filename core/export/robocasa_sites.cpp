#include "core/export/robocasa_sites.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace sagrid::exportdetail {

namespace {

constexpr float kBurnerHalfHeight = 0.005f;
constexpr float kMinBurnerRadius = 0.03f;
constexpr float kMaxBurnerRadius = 0.15f;
constexpr float kPointSiteRadius = 0.008f;

// Which third of [lo, hi] a value falls in: -1 low, 0 middle, +1 high; all 0 for a span below
// `tolerance` (burners in one row or column).
int band(float value, float lo, float hi, float tolerance) {
  if (hi - lo < tolerance) return 0;
  const float t = (value - lo) / (hi - lo);
  return t < 1.0f / 3.0f ? -1 : (t > 2.0f / 3.0f ? 1 : 0);
}

std::string uniqueName(const std::string& base, std::set<std::string>& taken) {
  std::string name = base;
  for (int n = 2; taken.count(name); ++n) name = base + "_" + std::to_string(n);
  taken.insert(name);
  return name;
}

float burnerRadius(const std::vector<Eigen::Vector2f>& burners, std::size_t i,
                   const Eigen::AlignedBox3f& bounds) {
  float nearest = std::numeric_limits<float>::infinity();
  for (std::size_t j = 0; j < burners.size(); ++j) {
    if (j != i) nearest = std::min(nearest, (burners[j] - burners[i]).norm());
  }
  // Neighbouring burners leave a gap; a lone burner takes a quarter of the smaller top side.
  const float radius = std::isfinite(nearest)
                           ? 0.4f * nearest
                           : 0.25f * std::min(bounds.sizes().x(), bounds.sizes().y());
  return std::clamp(radius, kMinBurnerRadius, kMaxBurnerRadius);
}

}  // namespace

std::vector<std::string> burnerLocations(const std::vector<Eigen::Vector2f>& burners) {
  std::vector<std::string> names;
  if (burners.empty()) return names;
  Eigen::Vector2f lo = burners.front(), hi = burners.front();
  for (const auto& b : burners) lo = lo.cwiseMin(b), hi = hi.cwiseMax(b);
  // Burners closer than a quarter of the layout's larger span count as one row or column.
  const float tolerance = std::max(0.03f, 0.25f * (hi - lo).maxCoeff());
  std::set<std::string> taken;
  for (const auto& b : burners) {
    const int column = band(b.x(), lo.x(), hi.x(), tolerance);
    const int row = band(b.y(), lo.y(), hi.y(), tolerance);
    const char* side = column < 0 ? "left" : (column > 0 ? "right" : "center");
    std::string base;
    if (burners.size() == 1) {
      base = "center";
    } else if (hi.y() - lo.y() < tolerance) {  // one row: left, center, right
      base = side;
    } else {
      // Front faces -y; a burner in the middle row is "center", "left" or "right".
      base = row == 0 ? std::string(side) : std::string(row > 0 ? "rear_" : "front_") + side;
    }
    names.push_back(uniqueName(base, taken));
  }
  return names;
}

std::vector<MjcfSite> robocasaSites(const std::vector<SimulatorPoint>& points,
                                    const Eigen::AlignedBox3f& bounds,
                                    const std::string& category) {
  std::vector<Eigen::Vector2f> burners;
  std::vector<std::size_t> burnerIndex;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].type == "heatsource") {
      burners.push_back(points[i].position.head<2>());
      burnerIndex.push_back(i);
    }
  }
  const std::vector<std::string> locations = burnerLocations(burners);
  const bool hasWater =
      category == "sink" || std::any_of(points.begin(), points.end(),
                                        [](const auto& p) { return p.type == "fluidsource"; });

  // Knobs take the location of the burner nearest along x (knobs usually sit in a row below
  // their burners), each burner once while unclaimed burners remain.
  std::vector<std::size_t> knobs;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].type == "togglebutton") knobs.push_back(i);
  std::map<std::size_t, std::string> knobLocation;
  std::set<std::size_t> claimed;
  for (std::size_t k : knobs) {
    float best = std::numeric_limits<float>::infinity();
    std::size_t bestBurner = burners.size();
    for (int pass = 0; pass < 2 && bestBurner == burners.size(); ++pass) {
      for (std::size_t b = 0; b < burners.size(); ++b) {
        if (pass == 0 && claimed.count(b)) continue;
        const float d = std::abs(burners[b].x() - points[k].position.x());
        if (d < best) best = d, bestBurner = b;
      }
    }
    if (bestBurner < burners.size()) {
      claimed.insert(bestBurner);
      knobLocation[k] = locations[bestBurner];
    }
  }

  std::set<std::string> taken;
  std::map<std::string, int> perType;
  std::vector<MjcfSite> sites;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const SimulatorPoint& p = points[i];
    MjcfSite site{"", "sphere", p.position, {kPointSiteRadius, 0.0f}, p.type};
    if (p.type == "heatsource") {
      const std::size_t b =
          std::find(burnerIndex.begin(), burnerIndex.end(), i) - burnerIndex.begin();
      site.name = uniqueName("burner_on_" + locations[b], taken);
      site.shape = "cylinder";
      site.size = {burnerRadius(burners, b, bounds), kBurnerHalfHeight};
    } else if (p.type == "fluidsource") {
      site.name = uniqueName("water", taken);
      site.shape = "cylinder";
      site.size = {kWaterRadius, kWaterHalfHeight};
      site.position.z() -= kWaterHalfHeight;  // the stream hangs below the outlet
    } else if (p.type == "togglebutton" && knobLocation.count(i)) {
      site.name = uniqueName("knob_" + knobLocation[i], taken);
    } else if (p.type == "togglebutton" && hasWater) {
      site.name = uniqueName("handle", taken);
    } else {
      std::string base;
      for (unsigned char c : p.type) base.push_back(std::isalnum(c) ? std::tolower(c) : '_');
      site.name = uniqueName(
          (base.empty() ? "point" : base) + "_" + std::to_string(perType[p.type]++), taken);
    }
    sites.push_back(site);
  }
  return sites;
}

}  // namespace sagrid::exportdetail
