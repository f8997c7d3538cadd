#include "core/export/robocasa_sites.h"

#include "core/controls/control_pairing.h"

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

// Knob (point index) -> burner (index among the burners): the recorded pairing when every knob
// has one and no burner is driven twice, else the layout's.
std::map<std::size_t, std::size_t> knobBurners(const std::vector<SimulatorPoint>& points,
                                               const std::vector<std::size_t>& knobs,
                                               const std::vector<Eigen::Vector2f>& burners,
                                               const std::vector<std::string>& locations,
                                               std::vector<std::string>* warnings) {
  std::map<std::size_t, std::size_t> paired;
  bool recorded = !knobs.empty();
  std::set<int> driven;
  for (std::size_t k : knobs) {
    const std::optional<int>& d = points[k].drives;
    if (!d || *d >= static_cast<int>(burners.size()) || (*d >= 0 && !driven.insert(*d).second)) {
      if (d && warnings)
        warnings->push_back("knob point " + std::to_string(k + 1) + " drives heat source " +
                            std::to_string(*d) + ", which is not there or driven twice; knobs "
                            "paired by layout");
      recorded = false;
      break;
    }
  }
  if (recorded) {
    for (std::size_t k : knobs)
      if (*points[k].drives >= 0) paired[k] = static_cast<std::size_t>(*points[k].drives);
  } else {
    std::vector<Eigen::Vector2f> knobXy;
    for (std::size_t k : knobs) knobXy.push_back(points[k].position.head<2>());
    const std::vector<int> drives = pairKnobsWithBurners(knobXy, burners);
    for (std::size_t n = 0; n < knobs.size(); ++n)
      if (drives[n] >= 0) paired[knobs[n]] = static_cast<std::size_t>(drives[n]);
  }
  if (warnings) {
    std::set<std::size_t> lit;
    for (const auto& entry : paired) lit.insert(entry.second);
    for (std::size_t b = 0; b < burners.size(); ++b)
      if (!lit.count(b))
        warnings->push_back("burner_on_" + locations[b] +
                            " has no knob: RoboCasa never lights it (add or pair a knob)");
  }
  return paired;
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
                                    const std::string& category,
                                    std::vector<std::string>* warnings) {
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

  std::vector<std::size_t> knobs;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].type == "togglebutton") knobs.push_back(i);
  std::map<std::size_t, std::string> toggleName;
  if (hasWater) {
    std::vector<std::size_t> fromLeft = knobs;
    std::stable_sort(fromLeft.begin(), fromLeft.end(), [&](std::size_t a, std::size_t b) {
      return points[a].position.x() < points[b].position.x();
    });
    for (std::size_t n = 0; n < fromLeft.size(); ++n)
      toggleName[fromLeft[n]] = n == 0 ? "handle" : (n == 1 ? "handle_temp" : "handle_extra");
  } else if (!burners.empty()) {
    for (std::size_t k = 0; k < knobs.size(); ++k) toggleName[knobs[k]] = "knob_dummy";
    for (const auto& [knob, burner] : knobBurners(points, knobs, burners, locations, warnings))
      toggleName[knob] = "knob_" + locations[burner];
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
    } else if (p.type == "togglebutton" && toggleName.count(i)) {
      site.name = uniqueName(toggleName[i], taken);
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
