// Fuzz target: labels.json through readLabels, then what every command does with what it read:
// metersPerUnit, and a rewrite (toJson) that must read back.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "core/common/error.h"
#include "core/labels/labels.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = sagrid::fuzz::writeInputFile(data, size, "labels.json");
  sagrid::ObjectLabels labels;
  try {
    labels = sagrid::readLabels(path);
    (void)sagrid::metersPerUnit(labels);
  } catch (const sagrid::Error&) {
    return 0;
  }
  // What we read, we can write and read again (the GUI and annotate rewrite labels).
  try {
    (void)sagrid::parseLabels(sagrid::toJson(labels), path);
  } catch (const sagrid::Error&) {
    std::abort();  // accepted labels whose rewrite our own reader rejects
  }
  return 0;
}
