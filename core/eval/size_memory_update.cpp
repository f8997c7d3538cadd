#include "core/eval/size_memory_update.h"

#include <cstdio>

#include "core/common/error.h"

namespace sagrid {

SizeMemoryUpdate updateSizeMemory(const SizeMemory* earlier, const std::vector<UnitsCase>& curated,
                                  const std::vector<MemoryRecall>& candidates,
                                  const std::string& featureConfigHash) {
  if (earlier && earlier->featureConfigHash() != featureConfigHash)
    throw InvalidArgument("the units memory was built with other features than the models'");
  const auto cases = mergeCases(earlier ? casesOfMemory(*earlier) : std::vector<UnitsCase>{}, curated);
  if (cases.empty()) throw InvalidArgument("units memory: no curated objects to remember");
  SizeMemoryUpdate update;
  update.report = evaluateSizeMemory(cases, candidates, featureConfigHash);
  update.objects = cases.size();
  update.rightWithMemory = update.report.chosenLeavingSourceOut.back().right;
  update.change = pairedChange(update.report.namedAgainstChosen);
  for (const auto& o : update.report.namedAgainstChosen) update.rightNamedOnly += o.current == 0;
  const MemoryRecall& chosen = update.report.candidates[update.report.chosenOnAll];
  // The noise in objects, as the counts are.
  const double noiseObjects = update.change.noise * double(update.objects);
  char line[400];
  if (!update.change.clearlyBetter() || chosen.namedUnitsOnly()) {
    std::snprintf(
        line, sizeof line,
        "units memory refused: left out by source it guesses %zu of %zu right, the named "
        "units alone %zu (noise %.1f objects)%s",
        update.rightWithMemory, update.objects, update.rightNamedOnly, noiseObjects,
        update.change.clearlyBetter() ? ", but on all sources the named units alone guess best"
        : update.rightWithMemory > update.rightNamedOnly ? ", better by less than its noise"
                                                         : "");
    update.verdict = line;
    return update;
  }
  std::vector<RememberedSize> entries;
  for (const auto& c : cases) entries.push_back(c.object);
  update.memory.emplace(std::move(entries), featureConfigHash, chosen.farFactor, chosen.neighbours,
                        chosen.measures);
  std::snprintf(line, sizeof line,
                "units memory adopted: %zu objects, %s (left out by source %zu of %zu right, named "
                "units alone %zu, noise %.1f objects)",
                update.objects, recallName(chosen).c_str(), update.rightWithMemory, update.objects,
                update.rightNamedOnly, noiseObjects);
  update.verdict = line;
  return update;
}

}  // namespace sagrid
