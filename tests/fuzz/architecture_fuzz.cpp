// Fuzz target: architecture strings ("[3,1,16],[3,2,16,2]", Table I notation) and execution
// modes, as a model card or --arch gives them. What parses must print back to itself.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/common/error.h"
#include "core/model/architecture.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)sagrid::model::parseExecutionMode(text);
  } catch (const sagrid::Error&) {
  }
  sagrid::model::Architecture architecture;
  try {
    architecture = sagrid::model::Architecture::parse(text);
    (void)architecture.receptiveRadius();
  } catch (const sagrid::Error&) {
    return 0;
  }
  const auto again = sagrid::model::Architecture::parse(architecture.toString());
  if (again.layers != architecture.layers) std::abort();
  return 0;
}
