#include "core/eval/size_memory_loso.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

namespace sagrid {

namespace {

void count(UnitsScore& score, bool right, bool notMetres) {
  ++score.objects;
  score.right += right;
  score.notMetres += notMetres;
  score.notMetresRight += right && notMetres;
}

std::string factorName(double factor) {
  if (!std::isfinite(factor)) return "named units only (no memory)";
  char text[40];
  std::snprintf(text, sizeof text, "memory, far factor %.3g", factor);
  return text;
}

std::string cell(std::size_t right, std::size_t of) {
  return std::to_string(right) + " / " + std::to_string(of);
}

}  // namespace

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
                                   const std::vector<double>& factors,
                                   const std::string& featureConfigHash, int neighbours,
                                   double tolerance) {
  UnitsLosoReport report;
  report.factors = factors;
  report.tolerance = tolerance;
  std::vector<RememberedSize> entries;
  std::set<std::string> groups;
  for (const auto& c : cases) {
    entries.push_back(c.object);
    groups.insert(c.group);
  }
  report.groups.assign(groups.begin(), groups.end());
  const SizeMemory memory(entries, featureConfigHash, 1.0, neighbours);
  auto groupIndex = [&](const std::string& g) {
    return std::size_t(std::find(report.groups.begin(), report.groups.end(), g) - report.groups.begin());
  };
  // right[f][i]: case i's guess with factor f, its own source left out of the memory.
  std::vector<std::vector<bool>> right(factors.size(), std::vector<bool>(cases.size()));
  std::vector<std::vector<double>> guessed(factors.size(), std::vector<double>(cases.size()));
  report.byFactor.assign(factors.size(), std::vector<UnitsScore>(report.groups.size() + 1));
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const UnitsCase& c = cases[i];
    const UnitGuess named = guessMetersPerUnit(c.object.extentUnits, c.object.category);
    const bool notMetres = scaleRatio(c.object.metersPerUnit, 1.0) > tolerance;
    // Recalled once, judged with every factor.
    const auto expected = memory.expectedMeters(c.object.descriptor, c.object.category, c.object.source);
    for (std::size_t f = 0; f < factors.size(); ++f) {
      const UnitGuess guess =
          std::isfinite(factors[f]) && expected
              ? unlessFarFromExpectedSize(named, c.object.extentUnits, *expected, factors[f])
              : named;
      guessed[f][i] = guess.metersPerUnit;
      right[f][i] = scaleRatio(guess.metersPerUnit, c.object.metersPerUnit) <= tolerance;
      count(report.byFactor[f][groupIndex(c.group)], right[f][i], notMetres);
      count(report.byFactor[f].back(), right[f][i], notMetres);
    }
  }
  // The factor with the most right among `among`; ties go to the larger (fewer scaled files).
  auto choose = [&](auto among) {
    std::size_t best = 0, bestRight = 0;
    for (std::size_t f = 0; f < factors.size(); ++f) {
      std::size_t n = 0;
      for (std::size_t i = 0; i < cases.size(); ++i) n += among(i) && right[f][i];
      if (n > bestRight || (n == bestRight && factors[f] > factors[best])) {
        best = f;
        bestRight = n;
      }
    }
    return best;
  };
  std::set<std::string> sources;
  for (const auto& c : cases) sources.insert(c.object.source);
  report.chosenLeavingSourceOut.assign(report.groups.size() + 1, UnitsScore{});
  for (const auto& source : sources) {
    const std::size_t f = choose([&](std::size_t i) { return cases[i].object.source != source; });
    report.chosenBySource.emplace_back(source, factors[f]);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (cases[i].object.source != source) continue;
      const bool notMetres = scaleRatio(cases[i].object.metersPerUnit, 1.0) > tolerance;
      count(report.chosenLeavingSourceOut[groupIndex(cases[i].group)], right[f][i], notMetres);
      count(report.chosenLeavingSourceOut.back(), right[f][i], notMetres);
      if (!right[f][i]) {
        char line[300];
        std::snprintf(line, sizeof line, "%s (%s, %s): guessed %.3g, curated %.3g m per unit",
                      cases[i].object.id.c_str(), source.c_str(), cases[i].object.category.c_str(),
                      guessed[f][i], cases[i].object.metersPerUnit);
        report.wrongChosen.push_back(line);
      }
    }
  }
  report.chosenOnAll = factors.empty() ? 1.0 : factors[choose([](std::size_t) { return true; })];
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
  for (std::size_t f = 0; f < report.factors.size(); ++f)
    row(factorName(report.factors[f]), report.byFactor[f]);
  row("**memory, far factor chosen leaving each source out**", report.chosenLeavingSourceOut);
  md += "\nFactor chosen without each source:";
  std::map<double, std::size_t> chosen;
  for (const auto& [source, factor] : report.chosenBySource) ++chosen[factor];
  for (const auto& [factor, n] : chosen) {
    std::snprintf(line, sizeof line, " %.3g (%zu source%s)", factor, n, n == 1 ? "" : "s");
    md += line;
  }
  std::snprintf(line, sizeof line, "; on all of them: %.3g (kept in units_memory.json).\n",
                report.chosenOnAll);
  md += line;
  if (!report.wrongChosen.empty()) md += "\nWrong with the factor chosen leaving the source out:\n\n";
  for (const auto& wrong : report.wrongChosen) md += "- " + wrong + "\n";
  return md;
}

}  // namespace sagrid
