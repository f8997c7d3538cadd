// Whether a candidate model beats the current one on the same objects by more than chance: the
// one rule every guarded update decides by (DESIGN.md "Updates are guarded"). Each object has a
// figure under both (lower is better: an error in metres, curator edits, 1 for a category decided
// wrongly); the candidate is adopted only where the mean of its per-object changes is below zero
// by more than their standard error. A gain of a few millimetres or one object's category over a
// score of objects comes and goes with the seed; the current model keeps it.
#pragma once

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace sagrid {

// One object's figure under the current model and under the candidate.
struct ObjectFigures {
  double current = 0, candidate = 0;
};

struct PairedChange {
  std::size_t objects = 0;
  std::size_t lower = 0, higher = 0;      // objects whose figure the candidate lowers / raises
  double current = NAN, candidate = NAN;  // the means (groups weighed equally)
  // The standard error of candidate - current; NaN where a group has fewer than two objects (one
  // object cannot tell a gain from its noise).
  double noise = NAN;
  double change() const { return candidate - current; }
  // Beyond the noise by a relative hair, so that a tie in rounding (one object of n fixed and none
  // broken changes the mean by exactly its standard error, 1/n) is refused on every machine.
  bool clearlyBetter() const { return std::isfinite(noise) && change() < -noise * (1 + 1e-9); }
  // "adopted", "refused (better by less than its noise)" or "refused".
  std::string verdict() const;
  // The same rule read both ways, for reports that compare rather than adopt: "better beyond its
  // noise", "worse beyond its noise", "within its noise" or "too few objects to tell".
  std::string comparison() const;
};

// Objects in groups that count equally (stoves, sinks and look-alikes in a share right averaged
// over the classes): the means average the groups' means, the noise adds their variances.
// Empty groups are skipped.
PairedChange pairedChange(const std::vector<std::vector<ObjectFigures>>& groups);
inline PairedChange pairedChange(const std::vector<ObjectFigures>& objects) {
  return pairedChange(std::vector<std::vector<ObjectFigures>>{objects});
}

// The objects both maps have, by id.
std::vector<ObjectFigures> pairById(const std::map<std::string, double>& current,
                                    const std::map<std::string, double>& candidate);

}  // namespace sagrid
