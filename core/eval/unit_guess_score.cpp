#include "core/eval/unit_guess_score.h"

#include <cstdio>

#include "core/annotate/units_record.h"
#include "core/mesh/unit_guess.h"

namespace sagrid {

UnitGuessScore scoreUnitGuesses(const std::vector<std::pair<ObjectLabels, ObjectLabels>>& predictedAndCurated,
                                double factor) {
  UnitGuessScore score;
  for (const auto& [predicted, curated] : predictedAndCurated) {
    // What annotate recorded: its guess, or the units the object's source declared.
    const bool declared = predicted.object.extra.contains(kUnitsDeclaredByField);
    const double guessed =
        declared ? metersPerUnit(predicted)
                 : recordedUnitGuess(predicted.object).value_or(UnitGuess{}).metersPerUnit;
    const double truth = metersPerUnit(curated);
    score.declared += declared;
    const bool right = scaleRatio(guessed, truth) <= factor;
    const bool notMetres = scaleRatio(truth, 1.0) > factor;
    ++score.objects;
    score.right += right;
    score.notMetres += notMetres;
    score.notMetresRight += notMetres && right;
    if (!right) {
      char line[160];
      std::snprintf(line, sizeof line, "%s: guessed %g, curated %g", curated.object.id.c_str(), guessed, truth);
      score.wrong.push_back(line);
    }
  }
  return score;
}

std::string unitGuessMarkdown(const UnitGuessScore& score, double factor) {
  char line[400];
  std::snprintf(line, sizeof line,
                "# Units guess\n\n| objects | guess within %.2gx | files not in metres | of them guessed within %.2gx |\n"
                "|---:|---:|---:|---:|\n| %zu | %zu | %zu | %zu |\n\n",
                factor, factor, score.objects, score.right, score.notMetres, score.notMetresRight);
  std::string md = line;
  if (score.declared) {
    std::snprintf(line, sizeof line,
                  "%zu of the objects' units were declared by their source (provenance.json), not "
                  "guessed.\n\n",
                  score.declared);
    md += line;
  }
  for (const auto& w : score.wrong) md += "- " + w + "\n";
  return md;
}

}  // namespace sagrid
