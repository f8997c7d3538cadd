#include "core/export/simulator_geometry.h"

#include <algorithm>
#include <system_error>

#include "core/common/error.h"
#include "core/export/export_frame.h"
#include "core/export/export_units.h"
#include "core/mesh/mesh_import.h"
#include "core/mesh/triangle_subset.h"
#include "core/physics/convex_decomposition.h"

namespace sagrid::exportdetail {

namespace fs = std::filesystem;

namespace {

// OmniGibson simplifies every collision hull to at most 60 vertices (asset_conversion_utils.py,
// generate_collision_meshes -> simplify_convex_hull) for its GPU physics; MuJoCo takes that too.
constexpr int kMaxHullVertices = 60;

std::vector<physics::ConvexPart> collisionParts(const Mesh& mesh, const Eigen::AlignedBox3f& frame,
                                                const ExportOptions& options,
                                                std::vector<std::string>& warnings) {
  switch (options.collision) {
    case CollisionMode::None:
      return {};
    case CollisionMode::Hull:
      return {physics::convexHullPart(mesh, kMaxHullVertices)};
    case CollisionMode::Decompose: {
      physics::DecompositionOptions decomposition;
      decomposition.maxParts = options.maxCollisionParts;
      decomposition.maxVerticesPerPart = kMaxHullVertices;
      decomposition.frame = frame;
      if (options.progress) {
        decomposition.progress = [&options](float fraction, const std::string& stage) {
          options.progress(0.1f + 0.79f * std::clamp(fraction, 0.0f, 1.0f), "collision: " + stage);
        };
      }
      physics::Decomposition result = physics::decomposeConvex(mesh, decomposition);
      warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
      return std::move(result.parts);
    }
  }
  return {};
}

}  // namespace

SimulatorGeometry buildSimulatorGeometry(const ObjectLabels& labels, const fs::path& meshPath,
                                         const fs::path& labelsPath, const ExportOptions& options) {
  const fs::path shownLabels = labelsPath.empty() ? meshPath : labelsPath;
  SimulatorGeometry geometry;
  const UnitScale units = exportUnitScale(labels, shownLabels);
  if (units.warning) geometry.warnings.push_back(*units.warning);
  geometry.metersPerUnit = units.metersPerUnit;
  validateAffordancePositions(labels, units.metersPerUnit, shownLabels);
  const std::optional<double> curatedMass = curatedMassKg(labels, shownLabels);

  if (options.progress) options.progress(0.0f, "importing");
  const auto up = parseUpAxis(labels.object.up);
  if (!up) throw FileError(shownLabels, "object.up '" + labels.object.up + "' is not an axis");
  // Only regular files are opened: a FIFO or device would block or never end.
  std::error_code ec;
  if (fs::exists(meshPath, ec) && !fs::is_regular_file(meshPath, ec))
    throw FileError(meshPath, "is not a regular file (a folder, FIFO or device?)");
  // Data never chooses what is read: the files an OBJ names must lie in its own folder.
  containedMeshReferences(meshPath);
  geometry.mesh = importMesh(meshPath, ImportOptions(*up));
  if (!labels.object.sha256.empty() && labels.object.sha256 != geometry.mesh.sha256) {
    geometry.warnings.push_back(meshPath.string() +
                                ": differs from the mesh the labels were made for (sha256)");
  }
  for (auto& p : geometry.mesh.positions) p *= static_cast<float>(units.metersPerUnit);
  geometry.bounds = geometry.mesh.bounds();
  if (!geometry.bounds.min().allFinite() || !geometry.bounds.max().allFinite() ||
      geometry.bounds.min().cwiseAbs().maxCoeff() > kMaxCoordinateMeters ||
      geometry.bounds.max().cwiseAbs().maxCoeff() > kMaxCoordinateMeters) {
    throw FileError(meshPath,
                    "coordinates reach farther than 10 km once in metres; check the "
                    "units (object.units / object.meters_per_unit in labels.json)");
  }

  geometry.body = geometry.mesh;
  if (options.articulatedControls) {
    ControlSplit split =
        splitControls(labels, geometry.mesh, units.metersPerUnit, shownLabels, geometry.warnings);
    geometry.controls = std::move(split.controls);
    if (!geometry.controls.empty()) geometry.body = triangleSubset(geometry.mesh, split.body);
  }
  std::vector<std::string> shapeWarnings;  // about the mesh: named after it below
  geometry.visualParts = visualParts(geometry.body, shapeWarnings);
  geometry.collisionParts =
      collisionParts(geometry.body, geometry.bounds, options, shapeWarnings);
  if (options.progress) options.progress(0.9f, "mass");
  physics::MassOptions massOptions;
  massOptions.category = labels.object.category;
  geometry.mass = physics::estimateMassProperties(geometry.mesh, massOptions);
  shapeWarnings.insert(shapeWarnings.end(), geometry.mass.warnings.begin(),
                       geometry.mass.warnings.end());
  for (const auto& warning : shapeWarnings) {
    const std::string named = meshPath.string() + ": " + warning;
    if (std::find(geometry.warnings.begin(), geometry.warnings.end(), named) ==
        geometry.warnings.end())
      geometry.warnings.push_back(named);
  }
  if (curatedMass) {
    geometry.mass = physics::withMass(geometry.mass, *curatedMass);
    geometry.massFromLabels = true;
  }
  if (options.progress) options.progress(1.0f, "writing");
  return geometry;
}

std::vector<MjcfSite> simulatorSites(const ObjectLabels& labels,
                                     const SimulatorGeometry& geometry,
                                     std::vector<std::string>& warnings) {
  std::vector<SimulatorPoint> points;
  for (const auto& point : labels.affordances)
    points.push_back({point.type, toSimulatorFrame(labels, point.position, geometry.metersPerUnit), {}});
  for (const auto& control : geometry.controls) points[control.point].drives = control.drives;
  return robocasaSites(points, geometry.bounds, labels.object.category, &warnings);
}

}  // namespace sagrid::exportdetail
