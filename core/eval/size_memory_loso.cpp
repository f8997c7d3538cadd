#include "core/eval/size_memory_loso.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace sagrid {

namespace {

void count(UnitsScore& score, bool right, bool notMetres) {
  ++score.objects;
  score.right += right;
  score.notMetres += notMetres;
  score.notMetresRight += right && notMetres;
}

std::string cell(std::size_t right, std::size_t of) {
  return std::to_string(right) + " / " + std::to_string(of);
}

}  // namespace

std::vector<std::vector<SizeMeasure>> defaultMeasureSets() {
  return {{SizeMeasure::LargestExtent},
          {SizeMeasure::Height},
          {SizeMeasure::WorkSurface},
          {SizeMeasure::LargestExtent, SizeMeasure::Height, SizeMeasure::WorkSurface}};
}

std::vector<int> defaultNeighbourCounts() { return {1, 3, 5, 9}; }

std::vector<double> defaultFarFactors() { return {1.5, 2, 3, 4, 5, 8}; }

std::vector<MemoryRecall> recallCandidates(const std::vector<std::vector<SizeMeasure>>& measureSets,
                                           const std::vector<int>& neighbourCounts,
                                           const std::vector<double>& factors) {
  std::vector<MemoryRecall> candidates;
  for (const auto& measures : measureSets)
    for (const int k : neighbourCounts)
      for (const double factor : factors) candidates.push_back({measures, factor, k});
  candidates.push_back({});
  return candidates;
}

std::string recallName(const MemoryRecall& recall) {
  if (recall.namedUnitsOnly()) return "named units only (no memory)";
  std::string name = recall.measures.size() > 1 ? "memory (most agreed of " : "memory (";
  for (std::size_t i = 0; i < recall.measures.size(); ++i)
    name += (i ? ", " : "") + std::string(sizeMeasureWords(recall.measures[i]));
  char rest[60];
  std::snprintf(rest, sizeof rest, ", %d nearest), far factor %.3g", recall.neighbours, recall.farFactor);
  return name + rest;
}

std::vector<UnitsCase> casesOfMemory(const SizeMemory& memory) {
  std::vector<UnitsCase> cases;
  for (const auto& e : memory.entries()) cases.push_back({e, "memory"});
  return cases;
}

std::vector<UnitsCase> mergeCases(std::vector<UnitsCase> earlier, const std::vector<UnitsCase>& more) {
  for (const auto& c : more) {
    earlier.erase(std::remove_if(earlier.begin(), earlier.end(),
                                 [&](const UnitsCase& e) {
                                   return e.object.id == c.object.id && e.object.source == c.object.source;
                                 }),
                  earlier.end());
    earlier.push_back(c);
  }
  return earlier;
}

UnitsLosoReport evaluateSizeMemory(const std::vector<UnitsCase>& cases,
                                   const std::vector<MemoryRecall>& candidates,
                                   const std::string& featureConfigHash, double tolerance) {
  UnitsLosoReport report;
  report.candidates = candidates;
  report.tolerance = tolerance;
  std::vector<RememberedSize> entries;
  std::set<std::string> groups;
  for (const auto& c : cases) {
    entries.push_back(c.object);
    groups.insert(c.group);
  }
  report.groups.assign(groups.begin(), groups.end());
  // One memory per set of measures and number of objects recalled.
  using MemoryKey = std::pair<std::vector<SizeMeasure>, int>;
  std::map<MemoryKey, SizeMemory> memories;
  for (const auto& candidate : candidates) {
    const MemoryKey key{candidate.measures, candidate.neighbours};
    if (!candidate.namedUnitsOnly() && !memories.count(key))
      memories.emplace(key, SizeMemory(entries, featureConfigHash, 1.0, candidate.neighbours,
                                       candidate.measures));
  }
  auto groupIndex = [&](const std::string& g) {
    return std::size_t(std::find(report.groups.begin(), report.groups.end(), g) - report.groups.begin());
  };
  const std::size_t n = candidates.size();
  // right[k][i]: case i's guess with candidate k, its own source left out of the memory.
  std::vector<std::vector<bool>> right(n, std::vector<bool>(cases.size()));
  std::vector<std::vector<double>> guessed(n, std::vector<double>(cases.size()));
  std::vector<bool> namedRight(cases.size());
  report.byCandidate.assign(n, std::vector<UnitsScore>(report.groups.size() + 1));
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const UnitsCase& c = cases[i];
    const UnitGuess named = guessMetersPerUnit(c.object.units.largestExtent, c.object.category);
    const bool notMetres = scaleRatio(c.object.metersPerUnit, 1.0) > tolerance;
    namedRight[i] = scaleRatio(named.metersPerUnit, c.object.metersPerUnit) <= tolerance;
    // Recalled once per memory, judged with every factor.
    std::map<MemoryKey, std::optional<ExpectedSize>> expected;
    for (const auto& [key, memory] : memories)
      expected[key] = memory.expectedSize(c.object.descriptor, c.object.category, c.object.units,
                                          c.object.source);
    for (std::size_t k = 0; k < n; ++k) {
      const MemoryRecall& recall = candidates[k];
      const std::optional<ExpectedSize> e =
          recall.namedUnitsOnly() ? std::nullopt : expected.at({recall.measures, recall.neighbours});
      const UnitGuess guess =
          e ? unlessFarFromExpectedSize(named, c.object.units[e->measure], e->meters, recall.farFactor)
            : named;
      guessed[k][i] = guess.metersPerUnit;
      right[k][i] = scaleRatio(guess.metersPerUnit, c.object.metersPerUnit) <= tolerance;
      count(report.byCandidate[k][groupIndex(c.group)], right[k][i], notMetres);
      count(report.byCandidate[k].back(), right[k][i], notMetres);
    }
  }
  // The candidate with the most right among `among`; ties go to the larger factor (fewer scaled
  // files), then to the earlier candidate.
  auto choose = [&](auto among) {
    std::size_t best = 0, bestRight = 0;
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t r = 0;
      for (std::size_t i = 0; i < cases.size(); ++i) r += among(i) && right[k][i];
      if (r > bestRight || (r == bestRight && candidates[k].farFactor > candidates[best].farFactor)) {
        best = k;
        bestRight = r;
      }
    }
    return best;
  };
  std::set<std::string> sources;
  for (const auto& c : cases) sources.insert(c.object.source);
  report.chosenLeavingSourceOut.assign(report.groups.size() + 1, UnitsScore{});
  for (const auto& source : sources) {
    const std::size_t k = choose([&](std::size_t i) { return cases[i].object.source != source; });
    report.chosenBySource.emplace_back(source, k);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (cases[i].object.source != source) continue;
      const bool notMetres = scaleRatio(cases[i].object.metersPerUnit, 1.0) > tolerance;
      count(report.chosenLeavingSourceOut[groupIndex(cases[i].group)], right[k][i], notMetres);
      count(report.chosenLeavingSourceOut.back(), right[k][i], notMetres);
      report.namedAgainstChosen.push_back({namedRight[i] ? 0.0 : 1.0, right[k][i] ? 0.0 : 1.0});
      if (!right[k][i]) {
        char line[300];
        std::snprintf(line, sizeof line, "%s (%s, %s): guessed %.3g, curated %.3g m per unit",
                      cases[i].object.id.c_str(), source.c_str(), cases[i].object.category.c_str(),
                      guessed[k][i], cases[i].object.metersPerUnit);
        report.wrongChosen.push_back(line);
      }
    }
  }
  report.chosenOnAll = choose([](std::size_t) { return true; });
  return report;
}

std::string unitsLosoMarkdown(const UnitsLosoReport& report) {
  char line[300];
  std::string md = "# Units guess, each source left out of the size memory\n\n";
  std::snprintf(line, sizeof line,
                "Right: the guess within %.3gx of the curated units; not in metres: curated units "
                "more than %.3gx from 1. Each cell: right / objects, then right / not in metres.\n\n",
                report.tolerance, report.tolerance);
  md += line;
  md += "| guess |";
  for (const auto& g : report.groups) md += " " + g + " |";
  md += " all |\n|---|";
  for (std::size_t g = 0; g <= report.groups.size(); ++g) md += "---:|";
  md += "\n";
  auto row = [&](const std::string& name, const std::vector<UnitsScore>& scores) {
    md += "| " + name + " |";
    for (const auto& s : scores)
      md += " " + cell(s.right, s.objects) + "; " + cell(s.notMetresRight, s.notMetres) + " |";
    md += "\n";
  };
  for (std::size_t k = 0; k < report.candidates.size(); ++k)
    row(recallName(report.candidates[k]), report.byCandidate[k]);
  row("**chosen leaving each source out**", report.chosenLeavingSourceOut);
  md += "\nChosen without each source:";
  std::map<std::size_t, std::size_t> chosen;
  for (const auto& [source, k] : report.chosenBySource) ++chosen[k];
  for (const auto& [k, n] : chosen) {
    std::snprintf(line, sizeof line, " %s (%zu source%s);", recallName(report.candidates[k]).c_str(), n,
                  n == 1 ? "" : "s");
    md += line;
  }
  md += " on all of them: " + recallName(report.candidates[report.chosenOnAll]) +
        " (kept in units_memory.json).\n";
  const PairedChange change = pairedChange(report.namedAgainstChosen);
  std::snprintf(
      line, sizeof line,
      "\nObject by object against the named units alone: %zu fixed, %zu broken (noise %.1f "
      "objects): %s.\n",
      change.lower, change.higher, change.noise * double(change.objects),
      change.comparison().c_str());
  md += line;
  if (!report.wrongChosen.empty()) md += "\nWrong with the recall chosen leaving the source out:\n\n";
  for (const auto& wrong : report.wrongChosen) md += "- " + wrong + "\n";
  return md;
}

}  // namespace sagrid
