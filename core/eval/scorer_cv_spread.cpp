#include "core/eval/scorer_cv_spread.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <sstream>

#include "core/common/error.h"
#include "core/eval/sample_stats.h"

namespace sagrid {

namespace {

// Edits per hand point, one-key share (percent) and single-point error (cm) of one figure set.
std::array<double, 3> numbersOf(const PointChoiceFigures& f) {
  return {f.editsPerHandPoint(), 100 * f.effort.oneKeyShare, 100 * f.singleError};
}

std::string row(const std::string& name, const std::array<double, 3>& all,
                const std::array<double, 3>& unseen) {
  char line[256];
  std::snprintf(line, sizeof line, "| %s | %.3f | %.0f %% | %.1f | %.3f | %.0f %% | %.1f |\n",
                name.c_str(), all[0], all[1], all[2], unseen[0], unseen[1], unseen[2]);
  return line;
}

}  // namespace

std::vector<CandidateSet> withoutSomeGenerated(const std::vector<CandidateSet>& sets,
                                               double share, unsigned seed) {
  if (!(share >= 0 && share < 1))
    throw InvalidArgument("the share of generated objects to leave out must lie in [0, 1)");
  std::set<std::string> objects;
  for (const CandidateSet& s : sets)
    if (s.generated) objects.insert(s.source + "/" + s.object);
  std::vector<std::string> order(objects.begin(), objects.end());
  // Fisher-Yates on the engine's raw numbers: the same draw with every standard library.
  std::mt19937 engine(seed);
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[engine() % i]);
  const auto leftOut = static_cast<std::size_t>(std::floor(share * static_cast<double>(order.size())));
  const std::set<std::string> drop(order.begin(), order.begin() + leftOut);
  std::vector<CandidateSet> out;
  for (const CandidateSet& s : sets)
    if (!s.generated || !drop.count(s.source + "/" + s.object)) out.push_back(s);
  return out;
}

ScorerCvSpread scorerCvSpread(const std::vector<CandidateSet>& sets,
                              const ScorerTrainingOptions& training,
                              const ScorerCurveOptions& curve, unsigned repeats, double share,
                              unsigned firstSeed) {
  ScorerCvSpread spread;
  spread.leftOutShare = share;
  spread.firstSeed = firstSeed;
  ScorerCurveOptions noCurve = curve;
  noCurve.ks.clear();
  for (unsigned r = 0; r < repeats; ++r) {
    const auto cv = crossValidatePointScorer(withoutSomeGenerated(sets, share, firstSeed + r),
                                             training, noCurve);
    spread.all.push_back(cv.withCurated);
    spread.unseen.push_back(cv.unseenWithCurated);
    spread.decisions.push_back(cv.decisions);
  }
  return spread;
}

std::string scorerCvSpreadMarkdown(const ScorerCvSpread& spread, const ScorerCrossValidation& full) {
  std::ostringstream md;
  md << "## Spread over repeats\n\n"
     << "The same leave one source out " << spread.all.size() << " times, each with "
     << std::lround(100 * spread.leftOutShare)
     << " % of the generated objects left out of training (a different draw each time, seeds "
     << spread.firstSeed << " to " << spread.firstSeed + spread.all.size() - 1
     << "): how far the figures move when the training changes a little. A difference between "
        "two designs smaller than this spread is not evidence; compare them on the same "
        "repeats.\n\n"
     << "| repeat | edits per hand point | one key | error, cm | unseen sources: edits | one key "
        "| error, cm |\n|---|---|---|---|---|---|---|\n"
     << row("every generated object (above)", numbersOf(full.withCurated),
            numbersOf(full.unseenWithCurated));
  std::array<std::vector<double>, 6> columns;
  for (std::size_t r = 0; r < spread.all.size(); ++r) {
    const auto a = numbersOf(spread.all[r]), u = numbersOf(spread.unseen[r]);
    md << row(std::to_string(spread.firstSeed + r), a, u);
    for (int c = 0; c < 3; ++c) columns[c].push_back(a[c]), columns[3 + c].push_back(u[c]);
  }
  if (spread.all.empty()) return md.str();
  std::array<SampleStats, 6> stats;
  for (int c = 0; c < 6; ++c) stats[c] = sampleStats(columns[c]);
  const auto pick = [&](double SampleStats::*field, int from) {
    return std::array<double, 3>{stats[from].*field, stats[from + 1].*field, stats[from + 2].*field};
  };
  md << row("**mean**", pick(&SampleStats::mean, 0), pick(&SampleStats::mean, 3))
     << row("sd", pick(&SampleStats::sd, 0), pick(&SampleStats::sd, 3))
     << row("lowest", pick(&SampleStats::lowest, 0), pick(&SampleStats::lowest, 3))
     << row("highest", pick(&SampleStats::highest, 0), pick(&SampleStats::highest, 3)) << "\n";
  return md.str();
}

nlohmann::json toJson(const ScorerCvSpread& spread) {
  nlohmann::json repeats = nlohmann::json::array();
  for (std::size_t r = 0; r < spread.all.size(); ++r)
    repeats.push_back({{"seed", spread.firstSeed + r},
                       {"with_curated", toJson(spread.all[r])},
                       {"unseen_with_curated", toJson(spread.unseen[r])},
                       {"held_out_decisions", toJson(spread.decisions[r])}});
  return {{"left_out_generated_share", spread.leftOutShare}, {"repeats", repeats}};
}

}  // namespace sagrid
