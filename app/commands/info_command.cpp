// `sagrid info MESH [--up y|z] [--resolution N] [--json]`: what SAGrid sees in a mesh file.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "app/command_registry.h"
#include "app/commands/up_axis_option.h"
#include "core/annotate/repeated_parts_pass.h"
#include "core/features/printed_marks.h"
#include "core/geometry/surface_scene.h"
#include "core/grid/mesh_summary.h"
#include "core/grid/normalization.h"
#include "core/mesh/mesh_import.h"
#include "core/points/touch_keys.h"

namespace {

void setupInfo(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "info", "Import a mesh and report triangles, vertices, bounding box (z-up mesh frame), the "
              "normalization into the unit cube, occupied voxels and the time per stage");
  struct Options {
    std::string mesh, up;
    int resolution = sagrid::kDefaultGridResolution;
    bool json = false, marks = false, keys = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("mesh", o->mesh, "Mesh file (.obj .gltf .glb .fbx .dae .ply .stl)")->required();
  sagrid::app::addUpAxisOption(*cmd, o->up, sagrid::app::kDetectedUpDefault);
  cmd->add_option("--resolution", o->resolution, "Grid resolution N for the occupancy count (N^3)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--json", o->json, "Print the report as one JSON object");
  cmd->add_flag("--printed-marks", o->marks,
                "Also list the circles printed on upward textured surfaces that the texture pass "
                "reads (cooking zones, touch symbols), in the file's frame");
  cmd->add_flag("--touch-keys", o->keys,
                "Also list the touch keys the touch-key pass finds (flat pads high on the object, "
                "parts of their own), in the file's frame");
  cmd->callback([o] {
    const auto summary = sagrid::summarizeMesh(o->mesh, sagrid::ImportOptions(sagrid::parseUpAxis(o->up), /*detect=*/true),
                                               o->resolution);
    if (o->json) std::cout << sagrid::summaryJson(summary).dump(2) << "\n";
    else std::cout << sagrid::formatSummary(summary);
    if (!o->marks && !o->keys) return;
    const sagrid::ImportOptions import(summary.fileUp, /*detect=*/false);
    const sagrid::Mesh mesh = sagrid::importMesh(o->mesh, import);
    auto list = [&](const char* kind, const std::vector<sagrid::PrintedCircle>& circles) {
      std::printf("%s: %zu\n", kind, circles.size());
      for (const auto& c : circles) {
        const Eigen::Vector3f p = sagrid::zUpToFile(c.centre, mesh.fileUp);
        std::printf("  centre (%g, %g, %g)  radius %g  support %.2f\n", p.x(), p.y(), p.z(), c.radius,
                    c.support);
      }
    };
    if (o->marks) {
      const sagrid::PrintedMarks marks = sagrid::findPrintedMarks(mesh);
      list("printed zones", marks.zones);
      list("printed symbols", marks.symbols);
    }
    if (o->keys) {
      const auto normalization = sagrid::Normalization::fromMesh(mesh);
      std::vector<sagrid::PrintedCircle> keys;
      const sagrid::SurfaceScene scene(mesh);
      for (const auto& key :
           sagrid::findTouchKeys(sagrid::normalizedParts(mesh, normalization), scene, normalization,
                                 sagrid::kDefaultGridResolution))
        keys.push_back(
            {normalization.toMesh(key.centre), normalization.lengthToMesh(key.radius), 1.0f});
      list("touch keys", keys);
    }
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("info", setupInfo);
