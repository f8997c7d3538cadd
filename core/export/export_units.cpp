#include "core/export/export_units.h"

#include <cmath>

#include "core/common/error.h"

namespace sagrid::exportdetail {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::optional<double> namedUnit(const std::string& unit) {
  if (unit == "m") return 1.0;
  if (unit == "cm") return 0.01;
  if (unit == "mm") return 0.001;
  if (unit == "in") return 0.0254;
  if (unit == "ft") return 0.3048;
  return std::nullopt;
}

const json* field(const json& object, const char* name) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(name);
  return it == object.end() ? nullptr : &*it;
}

}  // namespace

UnitScale exportUnitScale(const ObjectLabels& labels, const fs::path& labelsPath) {
  if (const json* value = field(labels.object.extra, "meters_per_unit")) {
    if (!value->is_number()) {
      throw FileError(labelsPath, "object.meters_per_unit must be a number (got " +
                                      value->dump().substr(0, 40) + ")");
    }
    const double m = value->get<double>();
    if (!std::isfinite(m) || m < kMinMetersPerUnit || m > kMaxMetersPerUnit) {
      throw FileError(labelsPath, "object.meters_per_unit must lie between 1e-6 and 1000 (got " +
                                      value->dump() + ")");
    }
    return {m, std::nullopt};
  }
  const std::pair<const char*, const json*> places[] = {{"object.units", &labels.object.extra},
                                                        {"units", &labels.extra}};
  for (const auto& [where, holder] : places) {
    const json* units = field(*holder, "units");
    if (!units) continue;
    if (!units->is_string()) {
      throw FileError(labelsPath, std::string(where) + " must be text such as \"m\" or \"cm\"");
    }
    if (auto m = namedUnit(units->get<std::string>())) return {*m, std::nullopt};
    return {1.0, labelsPath.string() + ": unknown " + where + " '" +
                     units->get<std::string>().substr(0, 20) +
                     "' (m, cm, mm, in, ft); metres assumed"};
  }
  return {1.0, labelsPath.string() +
                   ": units unknown (no object.units or object.meters_per_unit); metres assumed"};
}

std::optional<double> curatedMassKg(const ObjectLabels& labels, const fs::path& labelsPath) {
  const json* value = field(labels.object.extra, "mass_kg");
  if (!value || value->is_null()) return std::nullopt;
  const double mass = value->is_number() ? value->get<double>() : -1.0;
  if (!value->is_number() || !std::isfinite(mass) || mass <= 0.0 || mass > kMaxMassKg) {
    throw FileError(labelsPath, "object.mass_kg must be a number of kilograms in (0, 1e6] (got " +
                                    value->dump().substr(0, 40) + ")");
  }
  return mass;
}

void validateAffordancePositions(const ObjectLabels& labels, double metersPerUnit,
                                 const fs::path& labelsPath) {
  for (std::size_t i = 0; i < labels.affordances.size(); ++i) {
    const Eigen::Vector3d p = labels.affordances[i].position.cast<double>() * metersPerUnit;
    if (!p.allFinite() || p.cwiseAbs().maxCoeff() > kMaxCoordinateMeters) {
      throw FileError(labelsPath, "affordances[" + std::to_string(i) +
                                      "].position is not a usable coordinate (not finite or "
                                      "farther than 10 km once in metres)");
    }
  }
}

}  // namespace sagrid::exportdetail
