#include "core/eval/unit_guess_score.h"

#include <gtest/gtest.h>

#include "core/annotate/units_record.h"

namespace sagrid {
namespace {

std::pair<ObjectLabels, ObjectLabels> object(double guessed, double curated) {
  ObjectLabels predicted, truth;
  UnitGuess guess;
  guess.metersPerUnit = guessed;
  recordUnitGuess(predicted.object, guess);
  truth.object.id = "o";
  truth.object.extra["meters_per_unit"] = curated;
  return {predicted, truth};
}

TEST(UnitGuessScore, RightWithinTheFactorAndTheFilesNotInMetresApart) {
  const UnitGuessScore score =
      scoreUnitGuesses({object(1.0, 1.0), object(1.0, 0.69), object(0.01, 0.01), object(1.0, 0.18), object(0.001, 0.004)});
  EXPECT_EQ(score.objects, 5u);
  EXPECT_EQ(score.right, 3u);            // 1 vs 1, 1 vs 0.69 (1.45x), 0.01 vs 0.01
  EXPECT_EQ(score.notMetres, 3u);        // 0.01, 0.18, 0.004
  EXPECT_EQ(score.notMetresRight, 1u);   // the centimetres
  ASSERT_EQ(score.wrong.size(), 2u);
  EXPECT_EQ(score.wrong[0], "o: guessed 1, curated 0.18");
  EXPECT_EQ(score.declared, 0u);
}

TEST(UnitGuessScore, UnitsTheSourceDeclaredAreScoredAsRecordedAndCounted) {
  auto [predicted, truth] = object(1.0, 0.28);
  recordDeclaredUnits(predicted.object, 0.28, "provenance.json");
  const UnitGuessScore score = scoreUnitGuesses({{predicted, truth}, object(1.0, 0.28)});
  EXPECT_EQ(score.right, 1u);
  EXPECT_EQ(score.declared, 1u);
  EXPECT_NE(unitGuessMarkdown(score).find("1 of the objects' units were declared"),
            std::string::npos);
}

}  // namespace
}  // namespace sagrid
