// Fuzz target: NumPy .npz through readNpz (the ZIP reader, stored and deflate entries, zip64
// extras, CRC checks, then every .npy entry), and each array's conversions.
#include <cstddef>
#include <cstdint>

#include "core/common/error.h"
#include "core/io/npz.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = sagrid::fuzz::writeInputFile(data, size, "features.npz");
  try {
    for (const auto& [name, array] : sagrid::readNpz(path)) (void)array.asDouble();
  } catch (const sagrid::Error&) {
  }
  return 0;
}
