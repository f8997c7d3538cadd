// Fuzz target: a model card (<category>.<type>.json) through readModelCard, plus what loading
// does with its strings (architecture, execution mode).
#include <cstddef>
#include <cstdint>

#include "core/common/error.h"
#include "core/model/architecture.h"
#include "core/model/model_card.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = sagrid::fuzz::writeInputFile(data, size, "stove.heatsource.json");
  try {
    const auto card = sagrid::model::readModelCard(path);
    (void)card.sourceTag();
    (void)sagrid::model::Architecture::parse(card.architecture);
    (void)sagrid::model::parseExecutionMode(card.mode);
  } catch (const sagrid::Error&) {
  }
  return 0;
}
