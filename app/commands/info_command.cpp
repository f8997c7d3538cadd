// `sagrid info MESH [--up y|z] [--resolution N] [--json] [--same-geometry-as OTHER]`: what SAGrid
// sees in a mesh file.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/command_registry.h"
#include "app/commands/up_axis_option.h"
#include "core/annotate/point_passes.h"
#include "core/controls/control_part.h"
#include "core/controls/control_turn.h"
#include "core/geometry/crease_patches.h"
#include "core/geometry/material_parts.h"
#include "core/geometry/part_statistics.h"
#include "core/geometry/surface_scene.h"
#include "core/grid/mesh_summary.h"
#include "core/grid/normalization.h"
#include "core/labels/labels.h"
#include "core/mesh/geometry_identity.h"
#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_import.h"
#include "core/mesh/unit_guess.h"

namespace {

// The small parts (those the point candidates are seeded from), with the congruent copies of each
// (a candidate's part_copies feature).
void listSmallParts(const std::vector<sagrid::ConnectedPart>& parts, const sagrid::Normalization& n,
                    sagrid::UpAxis fileUp) {
  std::vector<std::size_t> small;
  for (std::size_t p = 0; p < parts.size(); ++p)
    if (sagrid::isSmallPart(parts[p], sagrid::PartContact{}.maxPartDiagonal)) small.push_back(p);
  std::printf("small parts: %zu of %zu\n", small.size(), parts.size());
  const sagrid::PartCopies copies(parts, sagrid::kCopyTolerance);
  for (std::size_t p : small) {
    const Eigen::Vector3f c = sagrid::zUpToFile(n.toMesh(parts[p].box.center()), fileUp);
    const Eigen::Vector3f size = parts[p].box.sizes() / n.scale;
    std::printf(
        "  part %zu: %d triangles, box centre (%g, %g, %g), size (%g, %g, %g) z-up, %zu copies%s\n",
        p, parts[p].triangles, c.x(), c.y(), c.z(), size.x(), size.y(), size.z(),
        copies.of(p).size(), parts[p].byCrease ? " (crease patch)" : "");
  }
}

void listMaterialParts(const sagrid::Mesh& mesh) {
  const auto parts = sagrid::materialParts(mesh);
  std::printf("material parts: %zu\n", parts.size());
  for (const auto& [material, part] : parts) {
    const Eigen::Vector3f c = sagrid::zUpToFile(part.box.center(), mesh.fileUp);
    const Eigen::Vector3f size = part.box.sizes();
    const std::string name = material >= 0 && material < static_cast<int>(mesh.materials.size())
                                 ? mesh.materials[std::size_t(material)].name
                                 : std::string("(none)");
    std::printf("  material %d '%s': %d triangles, box centre (%g, %g, %g), size (%g, %g, %g) z-up\n", material,
                name.c_str(), part.triangles, c.x(), c.y(), c.z(), size.x(), size.y(), size.z());
  }
}

// The statistics of the mesh's parts that the category classifier reads (where its file says so).
void listPartStatistics(const sagrid::Mesh& mesh) {
  const auto stats = sagrid::partStatistics(mesh);
  std::printf("part statistics (category inputs):\n");
  for (std::size_t i = 0; i < stats.size(); ++i)
    std::printf("  %s: %.3f\n", sagrid::kPartStatisticNames[i], stats[i]);
}

// The control part of each toggle button point of a labels file, as the exports cut and move it.
void listControls(const sagrid::Mesh& mesh, const std::string& labelsPath, float turn,
                  const std::string& turnedMesh) {
  const sagrid::ObjectLabels labels = sagrid::readLabels(labelsPath);
  std::vector<Eigen::Vector3f> points;
  for (const auto& point : labels.affordances)
    if (point.type == "togglebutton") points.push_back(sagrid::fileToZUp(point.position, mesh.fileUp));
  const sagrid::ControlParts controls = sagrid::findControlParts(mesh, points);
  std::printf("controls: %zu toggle button points\n", points.size());
  const Eigen::Matrix3f toFile = sagrid::fileToZUpRotation(mesh.fileUp).transpose();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& part = controls.parts[i];
    std::printf("  control %zu: ", i + 1);
    if (part) {
      const Eigen::Vector3f axis = toFile * part->axis;
      const Eigen::Vector3f pivot = sagrid::zUpToFile(part->pivot, mesh.fileUp);
      std::printf("%s (%s), %zu triangles, axis (%.3f, %.3f, %.3f), pivot (%g, %g, %g), radius %g",
                  sagrid::toString(part->motion), sagrid::toString(part->origin),
                  part->triangles.size(), axis.x(), axis.y(), axis.z(), pivot.x(), pivot.y(),
                  pivot.z(), part->radius);
    } else {
      std::printf("site only");
    }
    if (!controls.warnings[i].empty()) std::printf(" -- %s", controls.warnings[i].c_str());
    std::printf("\n");
  }
  if (turnedMesh.empty()) return;
  std::vector<sagrid::ControlPart> parts;
  for (const auto& part : controls.parts)
    if (part) parts.push_back(*part);
  sagrid::exportMesh(
      sagrid::turnControls(mesh, parts, turn, sagrid::pressAtTurn(turn, sagrid::metersPerUnit(labels))),
      turnedMesh);
  std::printf("controls turned by %g rad: %s\n", turn, turnedMesh.c_str());
}

void setupInfo(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "info", "Import a mesh and report triangles, vertices, bounding box (z-up mesh frame), the "
              "normalization into the unit cube, occupied voxels and the time per stage");
  struct Options {
    std::string mesh, up;
    int resolution = sagrid::kDefaultGridResolution;
    bool json = false, parts = false, materialParts = false, creasePatches = false;
    std::string controls, turnedMesh, unitsFor, sameGeometryAs;
    float turn = 0.6f;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("mesh", o->mesh, "Mesh file (.obj .gltf .glb .fbx .dae .ply .stl)")->required();
  sagrid::app::addUpAxisOption(*cmd, o->up, sagrid::app::kDetectedUpDefault);
  cmd->add_option("--resolution", o->resolution, "Grid resolution N for the occupancy count (N^3)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--json", o->json, "Print the report as one JSON object");
  cmd->add_flag(
      "--parts", o->parts,
      "Also list the mesh's small parts (a knob, a cap, a handle: those the point candidates "
      "are seeded from) and how many copies each has, and the statistics of the parts the "
      "category classifier reads (core/geometry/part_statistics.h)");
  cmd->add_flag("--crease-patches", o->creasePatches,
                "With --parts: list the small parts as a model whose card takes crease patches "
                "sees them (the shipped stove models): the crease patches beside the connected "
                "and material parts, each marked (core/geometry/crease_patches.h)");
  cmd->add_flag("--material-parts", o->materialParts,
                "Also list, per material, the connected parts of its triangles with their box "
                "centre in the file's frame and size: where zones, knobs and handles are drawn in "
                "a material of their own on a fused body, these are the curator's candidates");
  cmd->add_option("--controls", o->controls,
                  "Also list, for each toggle button point of this labels.json, the control part "
                  "the exports cut and move: knob, lever or button, where its part comes from "
                  "(connected, material, grown, disc), its triangles, axis and pivot (file frame)");
  cmd->add_option("--turned-mesh", o->turnedMesh,
                  "With --controls: also write the mesh with every control moved as the exports "
                  "move it (.obj or .glb, file frame): knobs and levers turned by --turn radians, "
                  "buttons pressed");
  cmd->add_option("--turn", o->turn, "Angle for --turned-mesh, radians")->capture_default_str();
  cmd->add_option("--same-geometry-as", o->sameGeometryAs,
                  "Also say whether this other mesh file has the same geometry "
                  "(core/mesh/geometry_identity.h): the same triangles, up to a translation and "
                  "within 1e-4 of the object's size, whatever their materials, colours, UVs, "
                  "format or order; the GUI carries a curated object's points to such twins, moved "
                  "by the offset printed (this file's box's lowest corner less the other's)");
  cmd->add_option("--units-for", o->unitsFor,
                  "Also print the units `annotate` guesses for this file were it of this category "
                  "(stove, sink, none): the unit, metres per unit and why");
  cmd->callback([o] {
    const auto summary = sagrid::summarizeMesh(o->mesh, sagrid::ImportOptions(sagrid::parseUpAxis(o->up), /*detect=*/true),
                                               o->resolution);
    std::optional<sagrid::UnitGuess> units;
    if (!o->unitsFor.empty())
      units = sagrid::guessMetersPerUnit(summary.bounds.sizes().maxCoeff(), o->unitsFor);
    std::optional<sagrid::GeometryMatch> twin;
    if (!o->sameGeometryAs.empty())  // any up axis: the match is in the files' own frames
      twin = sagrid::matchGeometry(
          sagrid::importMesh(o->sameGeometryAs, sagrid::ImportOptions(sagrid::UpAxis::Z)),
          sagrid::importMesh(o->mesh, sagrid::ImportOptions(sagrid::UpAxis::Z)));
    if (o->json) {
      nlohmann::json report = sagrid::summaryJson(summary);
      if (units)
        report["units_guess"] = {{"unit", units->unit}, {"meters_per_unit", units->metersPerUnit},
                                 {"sure", units->sure}, {"reason", units->reason}};
      if (!o->sameGeometryAs.empty())
        report["same_geometry"] = {
            {"mesh", o->sameGeometryAs},
            {"same", twin.has_value()},
            {"tolerance", sagrid::kSameGeometryTolerance},
            {"offset", twin ? nlohmann::json{twin->offset.x(), twin->offset.y(), twin->offset.z()}
                            : nlohmann::json(nullptr)},
            {"same_triangle_order", twin && twin->sameTriangleOrder}};
      std::cout << report.dump(2) << "\n";
    } else {
      std::cout << sagrid::formatSummary(summary);
      if (units)
        std::printf("units guess: %s, %g m per unit (%s)\n", units->unit.c_str(),
                    units->metersPerUnit, units->reason.c_str());
      if (!o->sameGeometryAs.empty()) {
        if (twin)
          std::printf("same geometry as %s: yes, offset %g %g %g (%s triangle order)\n",
                      o->sameGeometryAs.c_str(), twin->offset.x(), twin->offset.y(),
                      twin->offset.z(), twin->sameTriangleOrder ? "same" : "other");
        else
          std::printf("same geometry as %s: no\n", o->sameGeometryAs.c_str());
      }
    }
    if (!o->parts && !o->materialParts && o->controls.empty()) return;
    const sagrid::ImportOptions import(summary.fileUp, /*detect=*/false);
    const sagrid::Mesh mesh = sagrid::importMesh(o->mesh, import);
    if (o->materialParts) listMaterialParts(mesh);
    if (!o->controls.empty()) listControls(mesh, o->controls, o->turn, o->turnedMesh);
    if (!o->parts) return;
    const auto normalization = sagrid::Normalization::fromMesh(mesh);
    std::vector<sagrid::ConnectedPart> parts = sagrid::connectedAndMaterialParts(mesh);
    if (o->creasePatches)
      sagrid::appendNewParts(parts, sagrid::creasePatches(mesh), &sagrid::ConnectedPart::byCrease);
    listSmallParts(sagrid::normalizedParts(std::move(parts), normalization), normalization,
                   mesh.fileUp);
    listPartStatistics(mesh);
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("info", setupInfo);
