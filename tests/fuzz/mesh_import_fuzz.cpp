// Fuzz target: mesh import through the file code path (importMesh on a file named
// input<SAGRID_FUZZ_EXTENSION>), built once per format: .obj, .ply, .stl, .glb (with the glTF
// extensions' decoding of core/mesh/gltf_plain: Draco, meshopt, quantized accessors, WebP; seeded
// from the wild pool), .fbx (ASCII and binary), then the texture pass's reading of whatever it imported (printed marks on textured
// tops).
#include <cstddef>
#include <cstdint>

#include "core/common/error.h"
#include "core/features/printed_marks.h"
#include "core/mesh/mesh_import.h"
#include "fuzz_input_file.h"

#ifndef SAGRID_FUZZ_EXTENSION
#error "define SAGRID_FUZZ_EXTENSION, e.g. \".obj\""
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = sagrid::fuzz::writeInputFile(data, size, "input" SAGRID_FUZZ_EXTENSION);
  try {
    const sagrid::Mesh mesh = sagrid::importMesh(path);
    (void)sagrid::findPrintedMarks(mesh);
  } catch (const sagrid::Error&) {
    // A clear error is the right answer to a damaged mesh.
  }
  return 0;
}
