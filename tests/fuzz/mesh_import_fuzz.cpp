// Fuzz target: mesh import through the file code path (importMesh on a file named
// input<SAGRID_FUZZ_EXTENSION>), built once per format: .obj, .ply, .stl, .glb (with the glTF
// extensions' decoding of core/mesh/gltf_plain: Draco, meshopt, quantized accessors, WebP; seeded
// from the wild pool), .fbx (ASCII and binary), then the mesh's connected and material parts
// (what the point candidates are seeded from) of whatever it imported.
#include <cstddef>
#include <cstdint>

#include "core/common/error.h"
#include "core/geometry/material_parts.h"
#include "core/mesh/mesh_import.h"
#include "fuzz_input_file.h"

#ifndef SAGRID_FUZZ_EXTENSION
#error "define SAGRID_FUZZ_EXTENSION, e.g. \".obj\""
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = sagrid::fuzz::writeInputFile(data, size, "input" SAGRID_FUZZ_EXTENSION);
  try {
    const sagrid::Mesh mesh = sagrid::importMesh(path);
    (void)sagrid::connectedAndMaterialParts(mesh);  // connected parts, then material parts
  } catch (const sagrid::Error&) {
    // A clear error is the right answer to a damaged mesh.
  }
  return 0;
}
