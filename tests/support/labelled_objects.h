// Labelled objects on disk for export tests: a mesh file written from an in-memory mesh and a
// labels.json beside it, or a generated stove/sink with its ground-truth points.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/generate/generated_object.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh.h"

namespace sagrid::test {

AffordancePoint affordance(const std::string& type, const Eigen::Vector3f& position);

// Writes dir/mesh.obj (+ mesh.mtl) and dir/labels.json (object id, category, units "m" unless
// `units` is empty, the points). Returns the labels path.
std::filesystem::path writeLabelledObject(const std::filesystem::path& dir, const Mesh& mesh,
                                          const std::vector<AffordancePoint>& points,
                                          const std::string& id, const std::string& category,
                                          const std::string& units = "m");

// A generated object (metres, z up) written the same way with its ground-truth points.
std::filesystem::path writeGeneratedObject(const std::filesystem::path& dir,
                                           const gen::GeneratedObject& object,
                                           const std::string& id);

// Files the objects of `dataset` under the repositories `repos` in turn (object i under repos[i %
// size]) with a provenance record beside each mesh, as the corpora write: the sources that
// leave-one-source-out reads.
void assignSources(const std::filesystem::path& dataset, const std::vector<std::string>& repos);

// A one-square "stove" (dir/mesh.obj, z up) with a predicted heatsource and togglebutton, or
// (rejected) the same filed as "none" with them suggested as a stove's. Returns the labels path.
std::filesystem::path writeTinyStove(const std::filesystem::path& dir, bool rejected);

}  // namespace sagrid::test

namespace sagrid::test {

// A small analytic stove: a 0.6 x 0.5 x 0.1 m body (material "body", x in [-0.3, 0.3], y in
// [-0.25, 0.25], z in [0, 0.1]) with four knobs (material "knob") on its front (-y) face.
Mesh analyticStoveMesh();
// Writes it with four burners on top at (+-0.15, +-0.1, 0.1) and the four knobs' front centres.
std::filesystem::path writeAnalyticStove(const std::filesystem::path& dir,
                                         const std::string& id = "my_stove_01");

}  // namespace sagrid::test
