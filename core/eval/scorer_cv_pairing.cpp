#include "core/eval/scorer_cv_pairing.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/eval/sample_stats.h"

namespace sagrid {

namespace {

// A number of scorer_cv.json; null (a NaN when written) reads NaN.
double number(const nlohmann::json& j, const char* key) {
  const auto& v = j.at(key);
  return v.is_null() ? NAN : v.get<double>();
}

RecordedFigures figuresOf(const nlohmann::json& j) {
  return {number(j, "edits_per_hand_point"), number(j, "one_key_share"), number(j, "single_error_m"),
          number(j, "hand_points"), number(j, "objects")};
}

bool sameGround(const RecordedFigures& a, const RecordedFigures& b) {
  return a.handPoints == b.handPoints && a.objects == b.objects;
}

// Fewer / more / as many (within a millionth) of `paired` for `these`.
void count(const std::vector<PairedFigure>& paired, int& fewer, int& more, int& same) {
  for (const PairedFigure& p : paired) {
    const double d = p.difference();
    (std::abs(d) <= 1e-6 ? same : d < 0 ? fewer : more) += 1;
  }
}

// `d` as `format` prints its size, signed; a difference that prints as zero has no sign.
std::string differenceCell(double d, const char* format) {
  char cell[64];
  std::snprintf(cell, sizeof cell, format, std::abs(d));
  const bool zero = std::string(cell).find_first_of("123456789") == std::string::npos;
  return (zero ? "" : d > 0 ? "+" : "-") + std::string(cell);
}

}  // namespace

RecordedScorerCv readScorerCv(const std::filesystem::path& file) {
  const std::string text = readFileBytes(file);
  RecordedScorerCv run;
  run.file = file.string();
  try {
    const auto j = nlohmann::json::parse(text);
    run.all = figuresOf(j.at("all").at("with_curated"));
    run.unseen = figuresOf(j.at("unseen").at("with_curated"));
    if (j.contains("spread")) {
      const auto& spread = j.at("spread");
      run.leftOutShare = spread.at("left_out_generated_share").get<double>();
      for (const auto& r : spread.at("repeats")) {
        run.seeds.push_back(r.at("seed").get<unsigned>());
        run.repeatsAll.push_back(figuresOf(r.at("with_curated")));
        run.repeatsUnseen.push_back(figuresOf(r.at("unseen_with_curated")));
      }
    }
  } catch (const nlohmann::json::exception& e) {
    throw FileError(file, std::string("not a `sagrid scorer cv` report (scorer_cv.json): ") + e.what());
  }
  return run;
}

RecordedScorerCv pooledScorerCvs(const std::vector<RecordedScorerCv>& runs) {
  if (runs.empty()) throw InvalidArgument("no scorer cv runs to pool");
  const auto sameFigures = [](const RecordedFigures& a, const RecordedFigures& b) {
    return a.editsPerHandPoint == b.editsPerHandPoint && a.oneKeyShare == b.oneKeyShare &&
           sameGround(a, b);
  };
  RecordedScorerCv pooled = runs.front();
  std::map<unsigned, std::pair<RecordedFigures, RecordedFigures>> bySeed;
  for (const RecordedScorerCv& run : runs) {
    const std::string both = runs.front().file + " and " + run.file;
    if (!sameFigures(run.all, pooled.all) || !sameFigures(run.unseen, pooled.unseen))
      throw InvalidArgument(both + ": their full runs differ (another design or other objects): "
                                   "only runs of one design pool");
    if (run.leftOutShare != pooled.leftOutShare)
      throw InvalidArgument(both + ": the repeats left out other shares of the generated objects");
    for (std::size_t r = 0; r < run.seeds.size(); ++r)
      if (!bySeed.emplace(run.seeds[r], std::make_pair(run.repeatsAll[r], run.repeatsUnseen[r]))
               .second)
        throw InvalidArgument(both + ": seed " + std::to_string(run.seeds[r]) +
                              " repeats (give the later run --seed past the earlier's)");
    if (&run != &runs.front()) pooled.file += "+" + run.file;
  }
  pooled.seeds.clear();
  pooled.repeatsAll.clear();
  pooled.repeatsUnseen.clear();
  for (const auto& [seed, figures] : bySeed) {
    pooled.seeds.push_back(seed);
    pooled.repeatsAll.push_back(figures.first);
    pooled.repeatsUnseen.push_back(figures.second);
  }
  return pooled;
}

double signTestP(int fewer, int more) {
  const int n = fewer + more;
  if (n == 0) return 1.0;
  const int k = std::min(fewer, more);
  double tail = 0, term = std::pow(0.5, n);  // C(n, 0) / 2^n
  for (int i = 0; i <= k; ++i) {
    tail += term;
    term = term * (n - i) / (i + 1);
  }
  return std::min(1.0, 2 * tail);
}

PairedScorerCv pairScorerCvs(const RecordedScorerCv& these, const RecordedScorerCv& those) {
  const std::string both = these.file + " and " + those.file;
  if (these.seeds.empty() || those.seeds.empty())
    throw InvalidArgument(both + ": both runs need repeats (`scorer cv --repeats N`) to pair");
  if (these.seeds != those.seeds)
    throw InvalidArgument(both + ": the repeats do not pair (other repeat counts or seeds: " +
                          std::to_string(these.seeds.size()) + " from seed " +
                          std::to_string(these.seeds.front()) + " against " +
                          std::to_string(those.seeds.size()) + " from seed " +
                          std::to_string(those.seeds.front()) + ")");
  if (these.leftOutShare != those.leftOutShare)
    throw InvalidArgument(both + ": the repeats left out other shares of the generated objects");
  bool same = sameGround(these.all, those.all) && sameGround(these.unseen, those.unseen);
  for (std::size_t r = 0; r < these.seeds.size(); ++r)
    same = same && sameGround(these.repeatsAll[r], those.repeatsAll[r]) &&
           sameGround(these.repeatsUnseen[r], those.repeatsUnseen[r]);
  if (!same)
    throw InvalidArgument(both + ": measured on other curated objects (hand points or objects "
                                 "differ): make both runs from the same candidate files' objects");
  PairedScorerCv p;
  p.these = these.file;
  p.those = those.file;
  p.seeds = these.seeds;
  p.all = {these.all.editsPerHandPoint, those.all.editsPerHandPoint};
  p.unseen = {these.unseen.editsPerHandPoint, those.unseen.editsPerHandPoint};
  for (std::size_t r = 0; r < these.seeds.size(); ++r) {
    const auto &a = these.repeatsAll[r], &b = those.repeatsAll[r];
    p.edits.push_back({a.editsPerHandPoint, b.editsPerHandPoint});
    p.unseenEdits.push_back(
        {these.repeatsUnseen[r].editsPerHandPoint, those.repeatsUnseen[r].editsPerHandPoint});
    p.oneKey.push_back({a.oneKeyShare, b.oneKeyShare});
    p.error.push_back({100 * a.singleErrorM, 100 * b.singleErrorM});
  }
  count(p.edits, p.fewer, p.more, p.same);
  p.signTestP = signTestP(p.fewer, p.more);
  count(p.unseenEdits, p.unseenFewer, p.unseenMore, p.unseenSame);
  p.unseenSignTestP = signTestP(p.unseenFewer, p.unseenMore);
  return p;
}

std::string pairedScorerCvMarkdown(const PairedScorerCv& p) {
  std::ostringstream md;
  md << "## " << p.these << " against " << p.those << ", repeat by repeat\n\n"
     << "Edits per hand point (fewer is better), one key and the best point's error of each "
        "repeat; a difference is this run's less the other's. Read the mean difference against "
        "the sd of the differences, and the sign test over the repeats that differ.\n\n"
     << "| repeat | edits: this | other | difference | unseen sources: this | other | difference "
        "| one key: difference | error, cm: difference |\n|---|---|---|---|---|---|---|---|---|\n";
  char line[320];
  const auto row = [&](const std::string& name, const PairedFigure& e, const PairedFigure& u,
                       const std::string& oneKey, const std::string& error) {
    std::snprintf(line, sizeof line, "| %s | %.3f | %.3f | %s | %.3f | %.3f | %s | %s | %s |\n",
                  name.c_str(), e.these, e.those, differenceCell(e.difference(), "%.3f").c_str(),
                  u.these, u.those, differenceCell(u.difference(), "%.3f").c_str(), oneKey.c_str(),
                  error.c_str());
    md << line;
  };
  row("every generated object", p.all, p.unseen, "", "");
  std::vector<double> d, du, dk, de;
  for (std::size_t r = 0; r < p.seeds.size(); ++r) {
    const double k = 100 * p.oneKey[r].difference(), e = p.error[r].difference();
    row(std::to_string(p.seeds[r]), p.edits[r], p.unseenEdits[r],
        differenceCell(k, "%.0f") + " %", differenceCell(e, "%.1f"));
    d.push_back(p.edits[r].difference());
    du.push_back(p.unseenEdits[r].difference());
    dk.push_back(k);
    de.push_back(e);
  }
  const SampleStats s = sampleStats(d), su = sampleStats(du), sk = sampleStats(dk),
                    se = sampleStats(de);
  std::snprintf(line, sizeof line,
                "| **mean difference** (sd) | | | **%s** (%.3f) | | | **%s** (%.3f) | %s %% (%.0f) | "
                "%s (%.1f) |\n",
                differenceCell(s.mean, "%.3f").c_str(), s.sd, differenceCell(su.mean, "%.3f").c_str(),
                su.sd, differenceCell(sk.mean, "%.0f").c_str(), sk.sd,
                differenceCell(se.mean, "%.1f").c_str(), se.sd);
  md << line;
  std::snprintf(line, sizeof line,
                "| repeats with fewer / more / as many edits | | | %d / %d / %d | | | %d / %d / %d | "
                "| |\n| sign test, two-sided | | | p = %.3f | | | p = %.3f | | |\n\n",
                p.fewer, p.more, p.same, p.unseenFewer, p.unseenMore, p.unseenSame, p.signTestP,
                p.unseenSignTestP);
  md << line;
  return md.str();
}

}  // namespace sagrid
