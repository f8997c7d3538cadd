// What runs on an object after each model's network, and which steps of it are on: test-time
// augmentation, the coarse-to-fine crop and the learned point decision. `annotate` and
// `eval` take the same options and run the same sequence (core/annotate/point_passes.h), so an
// evaluation measures exactly what annotate writes.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sagrid {

struct PointScorer;

// The version of what the passes write: part of the annotation fingerprint's options hash, so a
// resumed batch predicts again the objects annotated before a pass changed. Raise it with every
// change to a pass's output (2-16: the hand-set passes' changes; 17: the touch-key pass removed;
// 18: every hand-set pass removed -- mirror pairs, repeated parts and burner caps, spout controls
// and outlets, part ownership, printed marks: under the learned decision none helped the
// wild-pool repositories no pass was made on, left out by source). The learned point decision is
// not a pass: its file's digest is part of the models' fingerprint.
inline constexpr int kPointPassesVersion = 18;

struct PassOptions {
  // Test-time augmentation: copies averaged per model (1 = off, 8 = all). 8 by default: on the
  // generated bench val split the paper error fell 4.55 -> 4.10 cm, on real-val 13.7 -> 9.4 cm,
  // real-dev unchanged (4.65 / 4.72 cm), for ~0.1-0.4 s more per object with two models.
  int symmetries = 8;
  // Coarse-to-fine: a second pass on a crop around each model's points (core/annotate/
  // coarse_to_fine.h), for small parts on large objects. Unset: as each model's card says
  // (point_extraction.coarse_to_fine); true / false: for every model.
  std::optional<bool> coarseToFine;
  // The learned point decision (core/annotate/point_scorer.h): each model's points are the
  // candidates its scorer chooses, where the models folder has one (point_scorer.json) and this
  // is on. Off: the count's points stand.
  bool learnedDecision = true;
  // The scorer itself, set from the models folder by withLearnedDecision (point_passes.h); null:
  // none. Not owned.
  const PointScorer* scorer = nullptr;
  // Keep every model's point candidates (before the scorer chooses) in CategoryPoints: what
  // `sagrid scorer` learns from.
  bool keepCandidates = false;
};

// The passes by name ("coarse_to_fine": the crop pass, off when switched off for every model) with
// how to tell and switch them off, for files that record which passes ran (a point scorer's
// candidates).
struct NamedPass {
  const char* name;
  bool (*isOff)(const PassOptions&);
  void (*switchOff)(PassOptions&);
};
const std::vector<NamedPass>& namedPasses();
// The names of the passes switched off in `passes`, in namedPasses() order.
std::vector<std::string> passesOff(const PassOptions& passes);

// A passes_off list as a file recorded it, without the names of removed passes (files written
// before session 33 name the hand-set passes their candidates were made without; those passes
// never run now). Throws InvalidArgument for a name that is neither a pass nor a removed one.
std::vector<std::string> recordedPassesOff(const std::vector<std::string>& names);

}  // namespace sagrid
