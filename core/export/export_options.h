// What a simulator export is asked to do (sagrid export flags, the GUI's export menu).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "core/common/contained_paths.h"
#include "core/export/omnigibson_model_name.h"

namespace sagrid {

// Collision geometry: none, the single convex hull of the object, or the convex decomposition
// (core/physics) that keeps cavities (basins, oven interiors) open.
enum class CollisionMode { None, Hull, Decompose };

std::optional<CollisionMode> parseCollisionMode(const std::string& text);  // "none|hull|decompose"
const char* toString(CollisionMode mode);

// Names handed out in one export run (a batch): folder names and OmniGibson model names stay
// unique across its objects.
struct ExportNames {
  UniqueFileNames folders;
  exportdetail::OmniGibsonModelNames models;
};

struct ExportOptions {
  CollisionMode collision = CollisionMode::Decompose;
  int maxCollisionParts = 32;
  // OmniGibson before the particlesource rename reads fluid outlets as "fluidsource".
  bool legacyFluidSource = false;
  // Long steps (convex decomposition, mass voxels) report here: fraction in [0,1], stage name.
  std::function<void(float fraction, const std::string& stage)> progress;
  // Shared by the objects of one batch; null: names are unique within this object only.
  ExportNames* names = nullptr;
  // A folder the user named (`--mesh-root`): a labels file's object.mesh may lead anywhere inside
  // it (annotate --out writes "../../data/x/mesh.glb"); empty: only inside the labels' folder.
  // The rule: core/dataset/labels_mesh.h.
  std::filesystem::path meshRoot;
  // Toggle buttons as moving parts (hinged knobs and levers, sliding buttons: core/controls);
  // false: sites only, the body one rigid piece (`--no-controls`).
  bool articulatedControls = true;
};

}  // namespace sagrid
