// `sagrid voxelize MESH --out FILE.npz|FILE.ply [--resolution N] [--up y|z]`.
#include <CLI/CLI.hpp>
#include <iostream>

#include "app/command_registry.h"
#include "app/commands/up_axis_option.h"
#include "core/grid/voxel_export.h"
#include "core/grid/voxelize.h"
#include "core/mesh/mesh_import.h"

namespace {

void setupVoxelize(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "voxelize", "Normalize a mesh into the unit cube and write its occupied voxels: .npz (\"coords\" "
                  "N x 3 indices, \"resolution\", \"center\", \"scale\") or .ply (voxel centres)");
  struct Options {
    std::string mesh, out, up;
    int resolution = sagrid::kDefaultGridResolution;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("mesh", o->mesh, "Mesh file (.obj .gltf .glb .fbx .dae .ply .stl)")->required();
  cmd->add_option("--out", o->out, "Output file, .npz or .ply")->required();
  cmd->add_option("--resolution", o->resolution, "Grid resolution N (N^3 voxels)")->check(CLI::Range(1, 1024));
  sagrid::app::addUpAxisOption(*cmd, o->up, "y for glTF/GLB, else z");
  cmd->callback([o] {
    sagrid::checkVoxelOutputPath(o->out);
    const sagrid::Mesh mesh = sagrid::importMesh(o->mesh, sagrid::ImportOptions(sagrid::parseUpAxis(o->up)));
    const auto normalization = sagrid::Normalization::fromMesh(mesh);
    const auto grid = sagrid::voxelize(sagrid::normalizedCopy(mesh, normalization), o->resolution);
    sagrid::writeVoxels(o->out, grid, normalization);
    std::cout << grid.occupiedCount() << " occupied voxels of " << o->resolution << "^3 written to " << o->out
              << "\n";
  });
}

}  // namespace

SAGRID_REGISTER_COMMAND("voxelize", setupVoxelize);
