// What runs on an object after each model's network, and which steps of it are on: test-time
// augmentation, the coarse-to-fine crop and the passes of the automatic count. `annotate` and
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
// change to a pass's output (2: part ownership drops knob and burner points on feet; 3: and keeps
// one point of a type per small part; 4: the touch-key pass; 5: on stoves, repeated parts as close
// as their spacing; 6: on stoves, part ownership drops strays from a full row; 7: a full row owns
// its parts, and every full row keeps its points; 8: on stoves, knob points move onto the knob
// parts they lie on or beside; 9: a touch symbol far from the others is no control; 10: oval
// touch symbols; 11: on stoves, a point beside a row of three or more knobs moves onto it whatever
// the field; 12: on stoves, burner caps repeat after part ownership; 13: on stoves, a larger knob
// continuing a row of three or more gets a point; 14: on sinks, a toggle point on the spout's part
// moves to a part beside it; 15: a rejected object keeps its likeliest category's points as
// suggestions; 16: every toggle button point records its control part, motion and burner; 17: the
// touch-key pass removed: on curated real objects no pass was made on it helped no source and
// hurt one). The learned point decision is not a pass: its file's digest is part of the models'
// fingerprint).
inline constexpr int kPointPassesVersion = 17;

struct PassOptions {
  // Test-time augmentation: copies averaged per model (1 = off, 8 = all). 8 by default: on the
  // generated bench val split the paper error fell 4.55 -> 4.10 cm, on real-val 13.7 -> 9.4 cm,
  // real-dev unchanged (4.65 / 4.72 cm), for ~0.1-0.4 s more per object with two models.
  int symmetries = 8;
  // Coarse-to-fine: a second pass on a crop around each model's points (core/annotate/
  // coarse_to_fine.h), for small parts on large objects. Unset: as each model's card says
  // (point_extraction.coarse_to_fine); true / false: for every model.
  std::optional<bool> coarseToFine;
  // The texture pass (core/annotate/printed_marks_pass.h): zones and touch symbols printed on a
  // stove's top become its heat-source and toggle points.
  bool printedMarks = true;
  // The mirror-pair pass of the automatic count (core/annotate/mirror_pairs_pass.h): on a
  // mirror-symmetric object, the twin of a point whose neighbourhood has the same shape there.
  bool mirrorPairs = true;
  // Within it, toggle buttons also paired across the spout beside them (a mixer's hot and cold
  // handles; completeAnchoredPairs).
  bool anchoredPairs = true;
  // The repeated-parts pass (core/annotate/repeated_parts_pass.h): a point on every copy of the
  // part a point lies on (a row of equal knobs).
  bool repeatedParts = true;
  // The spout-controls pass (core/annotate/spout_controls_pass.h), on sinks before the repeated
  // parts: a toggle point on the spout's part moves to the small part beside it where the field is
  // lowest (a widespread faucet's handle).
  bool spoutControls = true;
  // The spout-outlet pass (core/annotate/spout_outlet_pass.h): a fluid-source point on no
  // overhang moves to the outlet under the spout's tip near it.
  bool spoutOutlets = true;
  // The part-ownership pass (core/annotate/part_ownership_pass.h): one small part, one type (a
  // burner point on a knob goes), and knob points on the grate or the cabinet go when other knob
  // points lie on parts of their own.
  bool partOwnership = true;
  // The learned point decision (core/annotate/point_scorer.h): after the passes, each model's
  // points are the candidates its scorer chooses, where the models folder has one
  // (point_scorer.json) and this is on. Off: the passes' points stand.
  bool learnedDecision = true;
  // The scorer itself, set from the models folder by withLearnedDecision (point_passes.h); null:
  // none. Not owned.
  const PointScorer* scorer = nullptr;
  // Keep every model's point candidates (before the scorer chooses) in CategoryPoints: what
  // `sagrid scorer` learns from.
  bool keepCandidates = false;
};

// The passes by name ("printed_marks", "mirror_pairs", "anchored_pairs", "repeated_parts",
// "spout_controls", "spout_outlets", "part_ownership", and "coarse_to_fine": the crop pass, off
// when switched off for every model) with how to tell and switch them off, for files that record
// which passes ran (a point scorer's candidates).
struct NamedPass {
  const char* name;
  bool (*isOff)(const PassOptions&);
  void (*switchOff)(PassOptions&);
};
const std::vector<NamedPass>& namedPasses();
// The names of the passes switched off in `passes`, in namedPasses() order.
std::vector<std::string> passesOff(const PassOptions& passes);

}  // namespace sagrid
