// What a procedural generator produces: one merged mesh (metres, z up, before any realism
// transform) with its exact ground-truth affordance points and the parameters that made it.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/mesh/mesh.h"

namespace sagrid::gen {

struct GroundTruthPoint {
  std::string type;  // "heatsource", "togglebutton", "fluidsource"
  Eigen::Vector3f position = Eigen::Vector3f::Zero();
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
  // Triangles of the part the point belongs to (builder indices), used to keep the point within
  // tolerance of that part's surface.
  std::size_t triangleBegin = 0;
  std::size_t triangleEnd = 0;
};

struct GeneratedObject {
  std::string category;  // "stove" or "sink"
  Mesh mesh;
  std::vector<GroundTruthPoint> points;
  nlohmann::json generator = nlohmann::json::object();  // parameters, for variety tables
};

// Packs a finished generator run.
GeneratedObject makeGeneratedObject(std::string category, Mesh mesh,
                                    std::vector<GroundTruthPoint> points, nlohmann::json params);

// A length in metres rounded to the millimetre, as recorded in the generator parameters.
float roundedToMillimetre(float metres);

// Moves each point that lies farther than `maxDistance` from its part's triangles towards its
// closest point there, until it is `maxDistance` away. Centroids of thick parts (a big knob)
// otherwise sit inside the solid, farther from the surface than the ground-truth tolerance.
void keepPointsNearParts(const Mesh& mesh, std::vector<GroundTruthPoint>& points, float maxDistance);

}  // namespace sagrid::gen
