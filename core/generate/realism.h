// Makes a generated object look downloaded: ground truth kept within tolerance of its part,
// optional small vertex noise, colours as vertex colours or materials, a random yaw of the whole
// object, a random origin, and random units (m, cm, mm, in). The mesh leaves z-up in file units
// with Mesh::fileUp set for the writer; points are in the same frame (z-up, file units).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/generate/generated_object.h"
#include "core/generate/random.h"

namespace sagrid::gen {

// Ground-truth tolerance the generator guarantees (metres); tests check 1 cm against it.
inline constexpr float kGroundTruthMaxDistance = 0.008f;

struct RealismResult {
  std::string units = "m";
  double metersPerUnit = 1.0;
  nlohmann::json record = nlohmann::json::object();  // what was applied, for labels
};

RealismResult applyRealism(GeneratedObject& object, Rng& rng, UpAxis fileUp);

}  // namespace sagrid::gen
