// A guarded update of the size memory (core/annotate/size_memory.h) with newly curated objects,
// for `sagrid units memory` and the GUI's Train panel alike: the memory's objects and the new ones
// together (an object curated again replaces its entry), evaluated leaving each source out
// (core/eval/size_memory_loso.h), and a memory to write only where the recall chosen leaving each
// source out guesses units right more often than the named units alone, object by object, by more
// than the noise of that pairing (core/common/paired_change.h, the rule of every guard). Nothing
// is written here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/eval/size_memory_loso.h"

namespace sagrid {

struct SizeMemoryUpdate {
  UnitsLosoReport report;
  std::size_t objects = 0;
  std::size_t rightWithMemory = 0;  // left out by source, the recall chosen without each source
  std::size_t rightNamedOnly = 0;   // the named units alone
  PairedChange change;              // the share wrong, named units alone -> with the memory
  std::optional<SizeMemory> memory;  // the memory to write; empty when refused
  std::string verdict;               // one line: adopted or refused, and the figures
};

// `earlier`: the memory grown (none: built from `curated` alone). Throws InvalidArgument when
// there are no objects at all, or `earlier` was built with other features than
// `featureConfigHash`.
SizeMemoryUpdate updateSizeMemory(const SizeMemory* earlier, const std::vector<UnitsCase>& curated,
                                  const std::vector<MemoryRecall>& candidates,
                                  const std::string& featureConfigHash);

}  // namespace sagrid
