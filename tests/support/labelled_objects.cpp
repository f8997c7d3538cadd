#include "support/labelled_objects.h"

#include <fstream>

#include "core/annotate/suggested_points.h"
#include "core/common/atomic_file.h"
#include "core/dataset/dataset.h"
#include "core/dataset/object_source.h"
#include "core/mesh/mesh_export.h"

namespace sagrid::test {

namespace fs = std::filesystem;

AffordancePoint affordance(const std::string& type, const Eigen::Vector3f& position) {
  AffordancePoint point;
  point.type = type;
  point.position = position;
  return point;
}

fs::path writeLabelledObject(const fs::path& dir, const Mesh& mesh,
                             const std::vector<AffordancePoint>& points, const std::string& id,
                             const std::string& category, const std::string& units) {
  fs::create_directories(dir);
  exportMesh(mesh, dir / "mesh.obj");
  ObjectLabels labels;
  labels.object.id = id;
  labels.object.mesh = "mesh.obj";
  labels.object.category = category;
  if (!units.empty()) labels.object.extra["units"] = units;
  labels.affordances = points;
  writeLabels(dir / "labels.json", labels);
  return dir / "labels.json";
}

fs::path writeGeneratedObject(const fs::path& dir, const gen::GeneratedObject& object,
                              const std::string& id) {
  std::vector<AffordancePoint> points;
  for (const auto& p : object.points) points.push_back(affordance(p.type, p.position));
  return writeLabelledObject(dir, object.mesh, points, id, object.category);
}

void assignSources(const fs::path& dataset, const std::vector<std::string>& repos) {
  const auto entries = readDataset(dataset);
  for (std::size_t i = 0; i < entries.size(); ++i)
    writeFileAtomic(entries[i].mesh.parent_path() / kProvenanceRecordFile,
                    "{\"repo\": \"" + repos[i % repos.size()] + "\"}");
}

fs::path writeTinyStove(const fs::path& dir, bool rejected) {
  fs::create_directories(dir);
  std::ofstream(dir / "mesh.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
  ObjectLabels labels;
  labels.object.id = "stove";
  labels.object.mesh = "mesh.obj";
  labels.object.category = rejected ? "none" : "stove";
  labels.object.up = "z";
  labels.affordances = {affordance("heatsource", {0.5f, 0.5f, 0.0f}),
                        affordance("togglebutton", {0.5f, 0.5f, 0.0f})};
  if (rejected) markSuggestions(labels, "stove");
  writeLabels(dir / "labels.json", labels);
  return dir / "labels.json";
}

}  // namespace sagrid::test

#include "support/analytic_meshes.h"

namespace sagrid::test {

namespace {
constexpr float kKnobX[] = {-0.2f, -0.07f, 0.07f, 0.2f};
}

Mesh analyticStoveMesh() {
  Mesh mesh = box({-0.3f, -0.25f, 0.0f}, {0.3f, 0.25f, 0.1f});
  mesh.triangleMaterials.assign(mesh.triangles.size(), 0);
  for (float x : kKnobX) {
    Mesh knob = box({x - 0.015f, -0.27f, 0.035f}, {x + 0.015f, -0.25f, 0.065f});
    append(mesh, knob);
  }
  mesh.triangleMaterials.resize(mesh.triangles.size(), 1);
  mesh.materials = {Material{"body", {0.8f, 0.8f, 0.8f}, -1},
                    Material{"knob", {0.1f, 0.1f, 0.1f}, -1}};
  return mesh;
}

fs::path writeAnalyticStove(const fs::path& dir, const std::string& id) {
  std::vector<AffordancePoint> points;
  for (float x : {-0.15f, 0.15f})
    for (float y : {-0.1f, 0.1f}) points.push_back(affordance("heatsource", {x, y, 0.1f}));
  for (float x : kKnobX) points.push_back(affordance("togglebutton", {x, -0.27f, 0.05f}));
  return writeLabelledObject(dir, analyticStoveMesh(), points, id, "stove");
}

}  // namespace sagrid::test
