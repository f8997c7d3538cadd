// Fuzz target: one .npy file through readNpy; what it accepts must serialize and parse back to
// the same array.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "core/common/error.h"
#include "core/io/npz.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = sagrid::fuzz::writeInputFile(data, size, "array.npy");
  sagrid::NpyArray array;
  try {
    array = sagrid::readNpy(path);
    (void)array.asDouble();
  } catch (const sagrid::Error&) {
    return 0;
  }
  const auto again = sagrid::parseNpy(sagrid::serializeNpy(array), path);
  if (again.dtype != array.dtype || again.shape != array.shape || again.data != array.data)
    std::abort();
  return 0;
}
