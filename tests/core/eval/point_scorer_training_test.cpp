// The learned point decision fitted and measured leave one source out, on synthetic candidate sets
// whose true points are known: knobs (low field, one feature apart) among distractors.
#include "core/eval/point_scorer_training.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <random>

#include "core/annotate/point_scorer.h"
#include "core/common/error.h"
#include "core/eval/metrics.h"
#include "core/eval/point_scorer_update.h"
#include "core/eval/scorer_cv_spread.h"
#include "support/point_scorers.h"

namespace sagrid {
namespace {

// One model's candidates on one object: three knobs 0.3 m apart (the truth) and five distractors;
// the knobs' field is low and their "part_round_flat" is set, the distractors' not (with
// `overlap`, knobs and distractors share part of their ranges: a decision makes mistakes). The passes
// kept one knob and one distractor.
CandidateSet syntheticObject(const std::string& source, int index, bool generated,
                             std::mt19937& rng, float overlap) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const std::size_t d = candidateFeatureNames().size();
  const std::size_t roundFlat =
      std::find(candidateFeatureNames().begin(), candidateFeatureNames().end(), "part_round_flat") -
      candidateFeatureNames().begin();
  CandidateSet set;
  set.object = source + "-" + std::to_string(index);
  set.source = source;
  set.model = "stove.togglebutton";
  set.generated = generated;
  for (int c = 0; c < 8; ++c) {
    const bool knob = c < 3;
    PointCandidate candidate;
    candidate.position = Eigen::Vector3f(0.3f * c, 0.0f, 0.0f);
    candidate.kept = c == 0 || c == 3;
    candidate.features.resize(d);
    for (auto& f : candidate.features) f = u(rng);
    candidate.features[0] = knob ? (0.3f + overlap) * u(rng) : 0.5f - overlap + 0.5f * u(rng);
    candidate.features[roundFlat] = (u(rng) < (knob ? 1.0f - overlap : overlap)) ? 1.0f : 0.0f;
    candidate.distance = candidate.features[0];
    set.candidates.push_back(candidate);
    set.candidateSurface.push_back(candidate.position);
    if (candidate.kept) set.keptSurface.push_back(candidate.position);
    if (knob) set.truth.push_back(candidate.position);
  }
  return set;
}

std::vector<CandidateSet> syntheticSets(float overlap = 0.0f) {
  std::mt19937 rng(7);
  std::vector<CandidateSet> sets;
  for (const char* source : {"repo-a", "repo-b", "library-c"})
    for (int i = 0; i < 6; ++i) sets.push_back(syntheticObject(source, i, false, rng, overlap));
  for (int i = 0; i < 20; ++i) sets.push_back(syntheticObject("generated", i, true, rng, overlap));
  return sets;
}

std::size_t editsOn(const PointScorer& scorer, const std::vector<CandidateSet>& sets,
                    const std::string& source) {
  std::size_t edits = 0;
  for (const auto& s : sets) {
    if (s.source != source) continue;
    std::vector<Eigen::Vector3f> chosen;
    for (const auto& p : scoredPoints(*scorer.forModel(s.model), s.candidates, {}))
      chosen.push_back(p.position);
    edits += pointEdits(matchPoints(chosen, s.truth, s.metersPerUnit)).total();
  }
  return edits;
}

TEST(PointScorerTraining, TheScorerFindsTheKnownPointsOfObjectsItWasNotFittedOn) {
  const auto sets = syntheticSets();
  std::vector<const CandidateSet*> training;
  for (const auto& s : sets)
    if (s.source != "library-c") training.push_back(&s);
  for (bool trees : {true, false}) {
    ScorerTrainingOptions options;
    options.trees = trees;
    const PointScorer scorer = trainPointScorer(training, options);
    const ModelPointScorer* decision = scorer.forModel("stove.togglebutton");
    ASSERT_NE(decision, nullptr);
    EXPECT_EQ(decision->classifier.trees.has_value(), trees);
    for (const auto& s : sets) {
      if (s.source != "library-c") continue;
      const auto points = scoredPoints(*decision, s.candidates, {});
      ASSERT_EQ(points.size(), 3u) << s.object << (trees ? " (trees)" : " (logistic)");
      for (const auto& p : points) EXPECT_LT(p.position.x(), 0.7f) << s.object;  // a knob
    }
  }
  const PointScorer scorer = trainPointScorer(training, {});
  EXPECT_EQ(scorer.forModel("sink.fluidsource"), nullptr);
  // Candidates made with other passes cannot train one scorer.
  CandidateSet other = sets.front();
  other.passesOff = {"coarse_to_fine"};
  training.push_back(&other);
  EXPECT_THROW(trainPointScorer(training, {}), InvalidArgument);
}

// One model's candidates on one object where only the company tells the points: three knobs
// share one part shape and height that differ from object to object; the field marks one knob
// alone (the others' field is no lower than five distractors' of random shapes and heights).
CandidateSet knobsAlikeObject(const std::string& source, int index, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const auto& names = candidateFeatureNames();
  const auto at = [&](const char* name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const std::vector<std::size_t> shape = {at("part_size"), at("part_flatness"), at("part_roundness")};
  const std::vector<float> knobShape = {u(rng), u(rng), u(rng)};
  const float knobHeight = u(rng);
  CandidateSet set;
  set.object = source + "-" + std::to_string(index);
  set.source = source;
  set.model = "stove.togglebutton";
  for (int c = 0; c < 8; ++c) {
    const bool knob = c < 3;
    PointCandidate candidate;
    candidate.position = Eigen::Vector3f(0.3f * c, 0.0f, 0.0f);
    candidate.features.assign(names.size(), 0.5f);
    candidate.features[0] = c == 0 ? 0.1f * u(rng) : 0.3f + 0.7f * u(rng);
    candidate.features[at("on_part")] = 1;
    for (std::size_t k = 0; k < shape.size(); ++k)
      candidate.features[shape[k]] = knob ? knobShape[k] : u(rng);
    candidate.features[at("height")] = knob ? knobHeight : u(rng);
    candidate.distance = candidate.features[0];
    set.candidates.push_back(candidate);
    set.candidateSurface.push_back(candidate.position);
    if (knob) set.truth.push_back(candidate.position);
  }
  return set;
}

// 60 objects to train on and 20 held out, as knobsAlikeObject makes them.
struct KnobsAlike {
  std::vector<CandidateSet> sets, heldOut;
  std::vector<const CandidateSet*> training() const {
    std::vector<const CandidateSet*> out;
    for (const auto& s : sets) out.push_back(&s);
    return out;
  }
};
KnobsAlike knobsAlikeObjects(unsigned seed) {
  std::mt19937 rng(seed);
  KnobsAlike objects;
  for (int i = 0; i < 60; ++i) objects.sets.push_back(knobsAlikeObject("train", i, rng));
  for (int i = 0; i < 20; ++i) objects.heldOut.push_back(knobsAlikeObject("held-out", i, rng));
  return objects;
}

TEST(PointScorerTraining, ObjectsWhosePointsNoCandidateReachesCanBeLeftOut) {
  // Six objects whose knobs are printed where no candidate lies: every candidate, knob-like or
  // not, is a non-point there. Left out, the decision is the one fitted without them.
  const auto sets = syntheticSets(0.2f);
  std::vector<CandidateSet> printed;
  std::mt19937 rng(11);
  for (int i = 0; i < 6; ++i) {
    printed.push_back(syntheticObject("printed", i, false, rng, 0.2f));
    for (auto& t : printed.back().truth) t += Eigen::Vector3f(0.0f, 5.0f, 0.0f);
  }
  std::vector<const CandidateSet*> without, with;
  for (const auto& s : sets) without.push_back(&s), with.push_back(&s);
  for (const auto& s : printed) with.push_back(&s);
  ScorerTrainingOptions skip;
  skip.skipUnreached = true;
  const auto decision = [](const PointScorer& scorer) {
    return toJson(scorer).at("models").dump();
  };
  EXPECT_EQ(decision(trainPointScorer(with, skip)), decision(trainPointScorer(without, skip)));
  EXPECT_NE(decision(trainPointScorer(with, {})), decision(trainPointScorer(without, {})));
}

TEST(PointScorerTraining, TheSecondLookFindsThePartsThatLookLikeTheBestOne) {
  const KnobsAlike objects = knobsAlikeObjects(11);
  const auto& [sets, heldOut] = objects;
  const auto training = objects.training();
  ScorerTrainingOptions firstLookOnly;
  firstLookOnly.context = false;
  const PointScorer without = trainPointScorer(training, firstLookOnly);
  const PointScorer with = trainPointScorer(training, {});
  ASSERT_TRUE(with.forModel("stove.togglebutton")->classifier.contextTrees.has_value());
  EXPECT_FALSE(without.forModel("stove.togglebutton")->classifier.contextTrees.has_value());
  const std::size_t editsWithout = editsOn(without, heldOut, "held-out");
  const std::size_t editsWith = editsOn(with, heldOut, "held-out");
  // 60 knobs on the 20 objects: the first look finds about one per object, both looks together
  // half the others at least.
  EXPECT_GE(editsWithout, 30u);
  EXPECT_LE(2 * editsWith, editsWithout) << "with: " << editsWith;

  // Two curated objects, one all points and one without: no fold's first look can be fitted on
  // the other alone, and the decision is still trained (its context reads probabilities of 0).
  CandidateSet allPoints = sets[0], noPoint = sets[1];
  allPoints.truth = allPoints.candidateSurface;
  noPoint.truth.clear();
  const PointScorer two = trainPointScorer({&allPoints, &noPoint}, {});
  EXPECT_TRUE(two.forModel("stove.togglebutton")->classifier.contextTrees.has_value());
}

// Every object has three knobs: the learned count fills a choice whose thresholds stop short, and
// takes no fourth point.
TEST(PointScorerTraining, TheLearnedCountGrowsAChoiceToTheNumberOfPointsObjectsHave) {
  const KnobsAlike objects = knobsAlikeObjects(13);
  const auto& heldOut = objects.heldOut;
  const auto training = objects.training();
  ScorerTrainingOptions noCount;
  noCount.learnedCount = false;
  const PointScorer without = trainPointScorer(training, noCount);
  const PointScorer with = trainPointScorer(training, {});
  ASSERT_TRUE(with.forModel("stove.togglebutton")->countTrees.has_value());
  EXPECT_FALSE(without.forModel("stove.togglebutton")->countTrees.has_value());
  std::size_t fewerThanThree = 0;
  for (const auto& s : heldOut) {
    const auto withCount = scoredPoints(*with.forModel(s.model), s.candidates, {});
    EXPECT_EQ(withCount.size(), 3u) << s.object;
    fewerThanThree += scoredPoints(*without.forModel(s.model), s.candidates, {}).size() < 3;
  }
  EXPECT_GT(fewerThanThree, 0u);  // the thresholds alone stop short on some
  EXPECT_LE(editsOn(with, heldOut, "held-out"), editsOn(without, heldOut, "held-out"));
  // Without the second look there is no first look of unseen objects to learn the count on.
  ScorerTrainingOptions firstLookOnly;
  firstLookOnly.context = false;
  EXPECT_FALSE(
      trainPointScorer(training, firstLookOnly).forModel("stove.togglebutton")->countTrees);
}

// One stove of `n` burners and as many knobs: the burners' model sees them plainly (a low field
// on round flat parts), the knobs' model only dimly (knobs' and distractors' fields overlap, so
// their probabilities do not say how many there are).
std::pair<CandidateSet, CandidateSet> burnersAndKnobs(const std::string& source, int index,
                                                      std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const auto& names = candidateFeatureNames();
  const std::size_t roundFlat = static_cast<std::size_t>(
      std::find(names.begin(), names.end(), "part_round_flat") - names.begin());
  const auto modelSet = [&](const char* model, bool plain) {
    CandidateSet set;
    set.object = source + "-" + std::to_string(index);
    set.source = source;
    set.model = model;
    set.generated = source == "generated";
    for (std::size_t c = 0; c < 10; ++c) {
      const bool point = c < n;
      PointCandidate candidate;
      candidate.position = Eigen::Vector3f(0.3f * static_cast<float>(c), plain ? 0.0f : 1.0f, 0.0f);
      candidate.features.assign(names.size(), 0.5f);
      candidate.features[0] = plain ? (point ? 0.1f * u(rng) : 0.5f + 0.5f * u(rng))
                                    : (point ? 0.2f + 0.4f * u(rng) : 0.4f + 0.4f * u(rng));
      candidate.features[roundFlat] = plain && point ? 1.0f : 0.0f;
      candidate.distance = candidate.features[0];
      set.candidates.push_back(candidate);
      set.candidateSurface.push_back(candidate.position);
      if (point) set.truth.push_back(candidate.position);
    }
    return set;
  };
  return {modelSet("stove.heatsource", true), modelSet("stove.togglebutton", false)};
}

// The knobs' count reads the burners' model: told how many burners there are, the knobs' choice
// stops at as many, where their own probabilities leave it guessing.
TEST(PointScorerTraining, TheLearnedCountReadsTheCategorysOtherModels) {
  std::mt19937 rng(17);
  std::vector<CandidateSet> sets;
  for (const char* source : {"repo-a", "repo-b", "library-c", "generated"})
    for (int i = 0; i < 20; ++i) {
      auto [burners, knobs] = burnersAndKnobs(source, i, 1 + i % 5, rng);
      sets.push_back(std::move(burners));
      sets.push_back(std::move(knobs));
    }
  ScorerTrainingOptions alone;
  alone.otherModelsCount = false;
  const ScorerCrossValidation with = crossValidatePointScorer(sets, {});
  const ScorerCrossValidation without = crossValidatePointScorer(sets, alone);
  std::map<std::string, std::size_t> knobEdits;
  for (const auto* cv : {&with, &without})
    for (const auto& d : cv->decisions)
      if (d.model == "stove.togglebutton")
        knobEdits[cv == &with ? "with" : "without"] += d.edits.total();
  EXPECT_LT(4 * knobEdits["with"], 3 * knobEdits["without"])
      << knobEdits["with"] << " against " << knobEdits["without"];

  // Deciding one object: the burners' description changes the knobs' choice; none is no input.
  std::vector<const CandidateSet*> training;
  for (const auto& s : sets) training.push_back(&s);
  const PointScorer scorer = trainPointScorer(training, {});
  const ModelPointScorer& knobModel = *scorer.forModel("stove.togglebutton");
  std::mt19937 again(5);
  std::size_t right = 0;
  for (std::size_t n = 1; n <= 5; ++n) {
    const auto [burners, knobs] = burnersAndKnobs("held-out", static_cast<int>(n), n, again);
    const auto description =
        countDescription(*scorer.forModel("stove.heatsource"), burners.candidates);
    ASSERT_FALSE(description.empty());
    right += chosenCandidates(knobModel, knobs.candidates, {description}).size() == n;
  }
  EXPECT_GE(right, 4u);
  EXPECT_TRUE(countDescription(ModelPointScorer{}, sets.front().candidates).empty());
}

TEST(PointScorerTraining, FoldsLeaveOneSourceOutAndAreReproducible) {
  const auto sets = syntheticSets();
  const ScorerCrossValidation cv = crossValidatePointScorer(sets, {});
  ASSERT_EQ(cv.folds.size(), 3u);  // the generated objects are no fold: always in training
  EXPECT_EQ(cv.realObjects, 18u);
  EXPECT_EQ(cv.generatedObjects, 20u);
  for (const auto& fold : cv.folds) {
    EXPECT_EQ(fold.objects, 6u);
    // The passes kept one knob of three and a distractor: the distractor is dragged onto a knob
    // and the third knob added, 2 edits per object.
    EXPECT_EQ(fold.count.edits.total(), 12u) << fold.source;
    EXPECT_EQ(fold.withCurated.edits.total(), 0u) << fold.source;
    EXPECT_DOUBLE_EQ(fold.withCurated.effort.oneKeyShare, 1.0);
  }
  EXPECT_THROW(crossValidatePointScorer({sets.front()}, {}), InvalidArgument);
}

TEST(PointScorerTraining, TheLearningCurveDrawsFromTheOtherSourcesAndTotalsLeaveTunedSourcesOut) {
  const auto sets = syntheticSets(0.35f);
  ScorerCurveOptions curve;
  curve.ks = {0, 1000};  // none, and more than there are: every object of the other sources
  curve.tunedOn = {"repo-a"};
  const ScorerCrossValidation cv = crossValidatePointScorer(sets, {}, curve);
  ASSERT_EQ(cv.curve.size(), 2u);
  for (const auto& fold : cv.folds) {
    ASSERT_EQ(fold.curve.size(), 2u);
    EXPECT_EQ(fold.curve[0].edits.total(), fold.generatedOnly.edits.total()) << fold.source;
    EXPECT_EQ(fold.curve[1].edits.total(), fold.withCurated.edits.total()) << fold.source;
  }
  EXPECT_EQ(cv.unseenCount.effort.objects, 12u);  // repo-b and library-c
  EXPECT_EQ(cv.count.effort.objects, 18u);
  std::size_t unseenEdits = 0;
  for (const auto& fold : cv.folds)
    if (fold.source != "repo-a") unseenEdits += fold.withCurated.edits.total();
  EXPECT_EQ(cv.unseenWithCurated.edits.total(), unseenEdits);
  EXPECT_NE(scorerCrossValidationMarkdown(cv).find("sources no pass was made on"), std::string::npos);
}

TEST(PointScorerTraining, TheLearningCurvePoolsItsDrawsOnEveryFold) {
  const auto sets = syntheticSets(0.35f);
  ScorerCurveOptions one, three;
  one.ks = three.ks = {0, 2, 1000};
  three.draws = 3;
  const ScorerCrossValidation a = crossValidatePointScorer(sets, {}, one);
  const ScorerCrossValidation b = crossValidatePointScorer(sets, {}, three);
  ASSERT_EQ(a.folds.size(), b.folds.size());
  EXPECT_EQ(b.draws, 3u);
  for (std::size_t f = 0; f < a.folds.size(); ++f) {
    const auto& x = a.folds[f];
    const auto& y = b.folds[f];
    // Every object decided once per draw; none drawn or all drawn: the draws decide alike.
    EXPECT_EQ(y.curve[1].effort.objects, 3 * x.curve[1].effort.objects) << x.source;
    EXPECT_EQ(y.curve[0].edits.total(), 3 * x.curve[0].edits.total()) << x.source;
    EXPECT_EQ(y.curve[2].edits.total(), 3 * x.curve[2].edits.total()) << x.source;
    EXPECT_EQ(y.withCurated.edits.total(), x.withCurated.edits.total()) << x.source;
  }
  // The totals pool every fold's draws.
  std::size_t pooledEdits = 0;
  for (const auto& fold : b.folds) pooledEdits += fold.curve[1].edits.total();
  EXPECT_EQ(b.curve[1].edits.total(), pooledEdits);
  EXPECT_EQ(toJson(b)["learning_curve_draws"], 3);
  EXPECT_NE(scorerCrossValidationMarkdown(b).find("drawn 3 time(s) per fold"), std::string::npos);
}

TEST(ScorerCvSpread, EachRepeatLeavesOutWholeGeneratedObjectsOfItsOwnDraw) {
  auto sets = syntheticSets();
  // A second model's set for every object: a drawn object loses both.
  const std::size_t n = sets.size();
  for (std::size_t i = 0; i < n; ++i) {
    sets.push_back(sets[i]);
    sets.back().model = "stove.heatsource";
  }
  const auto kept = withoutSomeGenerated(sets, 0.25, 3);
  std::map<std::string, int> setsOf;
  std::size_t curated = 0;
  for (const auto& s : kept) {
    if (s.generated) ++setsOf[s.object];
    curated += !s.generated;
  }
  EXPECT_EQ(curated, 36u);          // every curated set stays
  EXPECT_EQ(setsOf.size(), 15u);    // 20 generated objects, 5 left out
  for (const auto& [object, count] : setsOf) EXPECT_EQ(count, 2) << object;
  const auto names = [](const std::vector<CandidateSet>& v) {
    std::vector<std::string> out;
    for (const auto& s : v) out.push_back(s.object + s.model);
    return out;
  };
  EXPECT_EQ(names(withoutSomeGenerated(sets, 0.25, 3)), names(kept));  // reproducible
  EXPECT_NE(names(withoutSomeGenerated(sets, 0.25, 4)), names(kept));  // another draw
  EXPECT_EQ(withoutSomeGenerated(sets, 0.0, 3).size(), sets.size());
  EXPECT_THROW(withoutSomeGenerated(sets, 1.0, 3), InvalidArgument);
}

TEST(ScorerCvSpread, RepeatsWithNothingLeftOutReadAsTheFullCrossValidation) {
  const auto sets = syntheticSets(0.35f);
  ScorerCurveOptions curve;
  curve.tunedOn = {"repo-a"};
  const ScorerCrossValidation full = crossValidatePointScorer(sets, {}, curve);
  const ScorerCvSpread same = scorerCvSpread(sets, {}, curve, 2, 0.0, 1);
  ASSERT_EQ(same.all.size(), 2u);
  for (std::size_t r = 0; r < 2; ++r) {
    EXPECT_EQ(same.all[r].edits.total(), full.withCurated.edits.total());
    EXPECT_EQ(same.unseen[r].edits.total(), full.unseenWithCurated.edits.total());
    // Each repeat lists its decisions object by object, as the full run does.
    EXPECT_EQ(toJson(same)["repeats"][r]["held_out_decisions"], toJson(full)["held_out_decisions"]);
  }
  // Most generated objects left out: every repeat still decides every unseen source's objects.
  const ScorerCvSpread fewer = scorerCvSpread(sets, {}, curve, 3, 0.9, 1);
  ASSERT_EQ(fewer.unseen.size(), 3u);
  EXPECT_EQ(fewer.unseen[0].effort.objects, 12u);  // repo-b and library-c, every repeat
  const std::string md = scorerCvSpreadMarkdown(fewer, full);
  EXPECT_NE(md.find("3 times, each with 90 % of the generated objects left out"), std::string::npos);
  EXPECT_NE(md.find("| **mean** |"), std::string::npos);
  EXPECT_EQ(toJson(fewer)["repeats"].size(), 3u);
}

TEST(PointScorerTraining, EachFoldIsDecidedByAScorerFittedWithoutItsSource) {
  // Knobs and distractors overlap, so a scorer fitted with a fold's objects would decide them
  // differently from one fitted without.
  const auto sets = syntheticSets(0.35f);
  const ScorerCrossValidation cv = crossValidatePointScorer(sets, {});
  std::size_t differs = 0;
  for (const auto& fold : cv.folds) {
    std::vector<const CandidateSet*> without, all;
    for (const auto& s : sets) {
      all.push_back(&s);
      if (s.source != fold.source) without.push_back(&s);
    }
    EXPECT_EQ(fold.withCurated.edits.total(), editsOn(trainPointScorer(without, {}), sets, fold.source))
        << fold.source;
    differs += fold.withCurated.edits.total() != editsOn(trainPointScorer(all, {}), sets, fold.source);
  }
  EXPECT_GT(differs, 0u);
  EXPECT_EQ(toJson(crossValidatePointScorer(sets, {})).dump(), toJson(cv).dump());
  // Every held-out (object, model) listed as its fold decided it: the folds' edits add up, the
  // first point's error is no less than the nearest candidate's.
  std::size_t real = 0, foldEdits = 0, listedEdits = 0;
  for (const auto& s : sets) real += !s.generated;
  for (const auto& fold : cv.folds) foldEdits += fold.withCurated.edits.total();
  ASSERT_EQ(cv.decisions.size(), real);
  for (const auto& d : cv.decisions) {
    listedEdits += d.edits.total();
    EXPECT_EQ(d.truthPoints, 3u) << d.object;
    EXPECT_GE(d.bestPointError, d.nearestCandidateError) << d.object;
    EXPECT_EQ(d.nearestCandidateError, 0.0) << d.object;  // the knobs are candidates
    EXPECT_EQ(d.truthReached, 3u) << d.object;
  }
  EXPECT_DOUBLE_EQ(cv.candidateRecall, 1.0);
  EXPECT_NE(scorerCrossValidationMarkdown(cv).find("| stove.togglebutton | " +
                                                   std::to_string(real) + " | " +
                                                   std::to_string(3 * real) + " of " +
                                                   std::to_string(3 * real) + " |"),
            std::string::npos)
      << scorerCrossValidationMarkdown(cv);
  // The per-model row ends with the points chosen and the edits by kind, summed over the held-out
  // decisions; every true point is reached, so no addition is unreachable.
  std::size_t chosen = 0;
  PointEdits byKind;
  for (const auto& d : cv.decisions) chosen += d.chosenPoints, byKind += d.edits;
  EXPECT_NE(scorerCrossValidationMarkdown(cv).find(
                " | " + std::to_string(chosen) + " | " + std::to_string(byKind.drags) + " | " +
                std::to_string(byKind.additions) + " (0) | " + std::to_string(byKind.deletions) +
                " | " + std::to_string(byKind.total()) + " | " +
                std::to_string(cv.trueCount.edits.total()) + " |\n"),
            std::string::npos)
      << scorerCrossValidationMarkdown(cv);
  EXPECT_EQ(listedEdits, foldEdits);
  EXPECT_EQ(toJson(cv)["held_out_decisions"].size(), real);
  // The same rankings cut at the true number of points: never a deletion (no more points than
  // the truth's), never fewer points than the truth's while candidates remain (every knob is one,
  // so no addition), the same hand points; totalled over the folds and reported.
  PointEdits trueCount;
  for (const auto& fold : cv.folds) {
    EXPECT_EQ(fold.trueCount.edits.deletions, 0u) << fold.source;
    EXPECT_EQ(fold.trueCount.edits.additions, 0u) << fold.source;
    EXPECT_EQ(fold.trueCount.edits.handPoints, fold.withCurated.edits.handPoints) << fold.source;
    trueCount += fold.trueCount.edits;
  }
  PointEdits listedTrueCount;
  for (const auto& d : cv.decisions) listedTrueCount += d.trueCountEdits;
  EXPECT_EQ(listedTrueCount.total(), trueCount.total());
  EXPECT_EQ(cv.trueCount.edits.total(), trueCount.total());
  EXPECT_EQ(toJson(cv)["all"]["true_count"]["edits"], trueCount.total());
  EXPECT_NE(scorerCrossValidationMarkdown(cv).find("## With the true number of points"),
            std::string::npos);
  EXPECT_NE(scorerCrossValidationMarkdown(cv).find("## The costliest decisions"), std::string::npos);

  // The object confidence's signal and outcome, one per curated object as its fold decided it:
  // as many right with one key as the folds count, and a calibration fitted on exactly them.
  std::size_t objects = 0;
  double oneKey = 0;
  for (const auto& fold : cv.folds) {
    objects += fold.withCurated.effort.objects;
    oneKey += fold.withCurated.effort.oneKeyShare * fold.withCurated.effort.objects;
  }
  ASSERT_EQ(cv.leastSure.size(), objects);
  ASSERT_EQ(cv.oneKey.size(), objects);
  EXPECT_NEAR(static_cast<double>(std::count(cv.oneKey.begin(), cv.oneKey.end(), true)), oneKey, 1e-9);
  for (double d : cv.leastSure) EXPECT_GT(d, 0.0);
  ASSERT_TRUE(cv.confidence.has_value());
  EXPECT_TRUE(cv.confidence->fitted);
  EXPECT_EQ(cv.confidence->objects, objects);
  EXPECT_NE(scorerCrossValidationMarkdown(cv).find("Object confidence, out of sample"), std::string::npos);
  // The AUC by hand: one right object surer than one wrong object, and a tie.
  ScorerCrossValidation three;
  three.leastSure = {0.01, 0.02, 0.02};
  three.oneKey = {true, false, true};
  EXPECT_DOUBLE_EQ(signalAuc(three), 0.75);

  // With tuned-on sources: the confidence fitted on their objects alone, and another one given,
  // checked on the other sources' objects (log loss and Brier by hand for the given map).
  ASSERT_EQ(cv.objectSources.size(), objects);
  EXPECT_TRUE(cv.unseenConfidence.empty());  // no source marked tuned-on
  ScorerCurveOptions tuned;
  tuned.tunedOn = {"repo-a"};
  ConfidenceCalibration half;
  half.fitted = true;  // P = 0.5 everywhere: log loss ln 2, Brier 0.25
  tuned.otherConfidence = half;
  tuned.otherConfidenceName = "a coin";
  const ScorerCrossValidation checked = crossValidatePointScorer(sets, {}, tuned);
  ASSERT_EQ(checked.unseenConfidence.size(), 2u);
  EXPECT_EQ(checked.unseenObjects, static_cast<std::size_t>(std::count(
                                       checked.objectSources.begin(), checked.objectSources.end(),
                                       std::string("repo-b")) +
                                   std::count(checked.objectSources.begin(),
                                              checked.objectSources.end(), std::string("library-c"))));
  EXPECT_EQ(checked.unseenConfidence[1].map, "a coin");
  EXPECT_NEAR(checked.unseenConfidence[1].logLoss, std::log(2.0), 1e-9);
  EXPECT_NEAR(checked.unseenConfidence[1].brier, 0.25, 1e-9);
  EXPECT_NEAR(checked.unseenConfidence[1].meanProbability, 0.5, 1e-9);
  EXPECT_TRUE(std::isfinite(checked.unseenConfidence[0].logLoss));
  EXPECT_NE(scorerCrossValidationMarkdown(checked).find("| a coin | 0.693 | 0.250 | 0.50 |"),
            std::string::npos)
      << scorerCrossValidationMarkdown(checked);
}

// A scorer that always takes one point: two edits per synthetic object.
PointScorer onePointScorer() {
  PointScorer scorer;
  scorer.byModel["stove.togglebutton"] = test::fieldOnlyScorer(-10);
  return scorer;
}

TEST(PointScorerTraining, TheGuardAdoptsABetterScorerAndRefusesAWorseOne) {
  const auto sets = syntheticSets();
  std::vector<const CandidateSet*> training;
  std::vector<CandidateSet> heldOut;
  for (const auto& s : sets)
    if (s.source == "library-c") heldOut.push_back(s);
    else training.push_back(&s);
  const PointScorer good = trainPointScorer(training, {});
  const PointScorer poor = onePointScorer();
  const ScorerGuard better = guardPointScorer(&poor, good, heldOut, training);
  EXPECT_TRUE(better.adopted);
  EXPECT_EQ(better.newEdits, 0u);
  EXPECT_EQ(better.currentEdits, 12u);  // one knob of three: two additions per object
  ASSERT_EQ(better.byModel.size(), 1u);
  EXPECT_EQ(better.byModel[0].handPoints, 18u);
  EXPECT_FALSE(guardPointScorer(&good, poor, heldOut, training).adopted);
  // Without a current scorer, against the points the candidates were made with (12 edits).
  EXPECT_TRUE(guardPointScorer(nullptr, good, heldOut, training).adopted);
  EXPECT_FALSE(guardPointScorer(nullptr, poor, heldOut, training).adopted);
  // One held-out object cannot tell a gain from its noise: the current decision stays.
  const ScorerGuard lone = guardPointScorer(&poor, good, {heldOut.front()}, training);
  EXPECT_EQ(lone.currentEdits, 2u);
  EXPECT_EQ(lone.newEdits, 0u);
  EXPECT_FALSE(lone.adopted);
  EXPECT_TRUE(std::isnan(lone.byModel[0].categoryNoise));
  EXPECT_NE(toString(lone.byModel[0]).find("the decision before stays (noise – edits)"),
            std::string::npos)
      << toString(lone.byModel[0]);
  // A held-out object that is also training data, or candidates of other passes: refused.
  std::vector<CandidateSet> leaked = heldOut;
  leaked.push_back(*training.front());
  EXPECT_THROW(guardPointScorer(&poor, good, leaked, training), InvalidArgument);
  std::vector<CandidateSet> otherPasses = heldOut;
  otherPasses.front().passesOff = {"coarse_to_fine"};
  EXPECT_THROW(guardPointScorer(&poor, good, otherPasses, training), InvalidArgument);
  EXPECT_THROW(guardPointScorer(&poor, good, {}, training), InvalidArgument);
}

// The synthetic knobs of one source held out twice: as stove.togglebutton and as `second` (the
// same knobs, judged as a second model); a good decision fitted on the other sources and a poor
// one (one point).
struct HeldOutTwice {
  std::vector<CandidateSet> sets = syntheticSets();
  std::vector<const CandidateSet*> training;
  std::vector<CandidateSet> heldOut;
  ModelPointScorer good, poor;
  explicit HeldOutTwice(const std::string& second) {
    for (const auto& s : sets)
      if (s.source == "library-c") {
        heldOut.push_back(s);
        heldOut.push_back(s);
        heldOut.back().model = second;
      } else {
        training.push_back(&s);
      }
    good = *trainPointScorer(training, {}).forModel("stove.togglebutton");
    poor = *onePointScorer().forModel("stove.togglebutton");
  }
};

bool sameDecision(const ModelPointScorer* a, const ModelPointScorer& b) {
  PointScorer x, y;
  x.byModel["m"] = *a;
  y.byModel["m"] = b;
  return toJson(x).dump() == toJson(y).dump();
}

// Without held-out objects the curated sources judge (issue 40: folds by source): each source's
// objects decided by a decision fitted on the other sources and the generated objects, against the
// current decision as it is, edits summed over the folds.
TEST(PointScorerTraining, TheGuardBySourceAdoptsABetterDecisionAndKeepsAnEqualOne) {
  const auto sets = syntheticSets();
  std::vector<const CandidateSet*> training;
  for (const auto& s : sets) training.push_back(&s);
  std::vector<int> folds;
  const PointScorer poor = onePointScorer();
  const auto better = guardPointScorerBySource(&poor, training, {}, [&](int k, int n) {
    folds.push_back(k);
    EXPECT_EQ(n, 3);
  });
  ASSERT_TRUE(better.has_value());
  EXPECT_EQ(folds, (std::vector<int>{0, 1, 2}));  // one fold per curated source, none generated
  ASSERT_EQ(better->byModel.size(), 1u);
  EXPECT_EQ(better->byModel[0].handPoints, 54u);  // 18 curated objects of three knobs each
  EXPECT_EQ(better->currentEdits, 36u);           // one knob of three: two additions per object
  EXPECT_EQ(better->newEdits, 0u);
  EXPECT_TRUE(better->adopted);
  EXPECT_TRUE(better->adoptedWhole());
  // A current decision as good as the new ones: nothing is adopted (ties keep the current one).
  const PointScorer good = trainPointScorer(training, {});
  const auto equal = guardPointScorerBySource(&good, training, {});
  ASSERT_TRUE(equal.has_value());
  EXPECT_EQ(equal->currentEdits, equal->newEdits);
  EXPECT_FALSE(equal->adopted);
  // Curated objects of one source cannot be judged by source.
  std::vector<const CandidateSet*> oneSource;
  for (const auto& s : sets)
    if (s.generated || s.source == "repo-a") oneSource.push_back(&s);
  EXPECT_FALSE(guardPointScorerBySource(&poor, oneSource, {}).has_value());
}

// Two models of two categories judged apart: the new scorer is better on one and worse on the
// other; the adopted scorer takes the new decision for the first and keeps the current one for
// the second.
TEST(PointScorerTraining, TheGuardAdoptsEachCategorysDecisionsOnItsOwnHeldOutObjects) {
  const HeldOutTwice c("sink.togglebutton");
  const auto& [sets, training, heldOut, good, poor] = c;
  PointScorer current, fresh;
  current.byModel = {{"stove.togglebutton", poor}, {"sink.togglebutton", good}, {"sink.fluidsource", poor}};
  fresh.byModel = {{"stove.togglebutton", good}, {"sink.togglebutton", poor}, {"stove.heatsource", good}};
  fresh.trainedOn = "fresh";
  const ScorerGuard guard = guardPointScorer(&current, fresh, heldOut, training);
  ASSERT_EQ(guard.byModel.size(), 3u);  // the two judged, then the new scorer's unjudged one
  EXPECT_EQ(guard.byModel[0].model, "sink.togglebutton");
  EXPECT_FALSE(guard.byModel[0].adopted);
  EXPECT_EQ(guard.byModel[1].model, "stove.togglebutton");
  EXPECT_TRUE(guard.byModel[1].adopted);
  EXPECT_EQ(guard.byModel[1].categoryAdoptedEdits, 0u);  // alone in its category: its own edits
  EXPECT_EQ(guard.byModel[1].categoryCurrentEdits, 12u);
  EXPECT_EQ(guard.byModel[1].categoryJudged, 1u);
  EXPECT_EQ(guard.byModel[2].model, "stove.heatsource");
  EXPECT_FALSE(guard.byModel[2].adopted);  // no held-out object judged it
  EXPECT_TRUE(guard.adopted);
  EXPECT_FALSE(guard.adoptedWhole());
  EXPECT_EQ(guard.adoptedEdits, 0u);  // the good decision on both models' objects
  EXPECT_EQ(guard.currentEdits, 12u);
  EXPECT_EQ(guard.newEdits, 12u);     // as many as before summed: a whole-scorer guard refused it
  EXPECT_EQ(toString(guard.byModel[1]),
            "stove.togglebutton: 12 -> 0 edits on 18 held-out points: adopted (noise 0.0 edits)");

  const PointScorer adopted = adoptedScorer(&current, fresh, guard);
  ASSERT_NE(adopted.forModel("stove.togglebutton"), nullptr);
  EXPECT_TRUE(sameDecision(adopted.forModel("stove.togglebutton"), good));
  EXPECT_TRUE(sameDecision(adopted.forModel("sink.togglebutton"), good));  // kept
  EXPECT_TRUE(sameDecision(adopted.forModel("sink.fluidsource"), poor));   // not judged: kept
  EXPECT_EQ(adopted.forModel("stove.heatsource"), nullptr);               // not judged: not taken
  EXPECT_NE(adopted.trainedOn.find("adopted for stove.togglebutton"), std::string::npos);
  // Without a current scorer, the adopted one holds the adopted models' decisions only.
  const ScorerGuard fromNone = guardPointScorer(nullptr, fresh, heldOut, training);
  const PointScorer onlyAdopted = adoptedScorer(nullptr, fresh, fromNone);
  EXPECT_NE(onlyAdopted.forModel("stove.togglebutton"), nullptr);
  EXPECT_EQ(onlyAdopted.forModel("sink.togglebutton"), nullptr);
}

// A category's models read each other (a knob per burner), so every mix of its current and new
// decisions is judged on the category's objects as a whole: the mix adopted is the best one judged,
// and the adopted scorer needs exactly the edits the guard reported.
TEST(PointScorerTraining, TheGuardJudgesEveryMixOfACategorysDecisions) {
  const HeldOutTwice c("stove.heatsource");
  const auto& [sets, training, heldOut, good, poor] = c;
  PointScorer current, mixed, better;
  current.byModel = {{"stove.togglebutton", poor}, {"stove.heatsource", good}};
  mixed.byModel = {{"stove.togglebutton", good}, {"stove.heatsource", poor}};
  // Current 12 edits (the knobs), all new 12 (the burners): as a whole no better, but the mix of
  // the new knobs and the current burners needs none.
  const ScorerGuard guard = guardPointScorer(&current, mixed, heldOut, training);
  ASSERT_EQ(guard.byModel.size(), 2u);
  EXPECT_EQ(guard.byModel[0].model, "stove.heatsource");
  EXPECT_FALSE(guard.byModel[0].adopted);
  EXPECT_TRUE(guard.byModel[1].adopted);
  for (const ScorerVerdict& v : guard.byModel) {
    EXPECT_EQ(v.categoryCurrentEdits, 12u) << v.model;
    EXPECT_EQ(v.categoryAdoptedEdits, 0u) << v.model;
    EXPECT_EQ(v.categoryJudged, 2u) << v.model;
  }
  EXPECT_EQ(guard.currentEdits, 12u);
  EXPECT_EQ(guard.newEdits, 12u);
  EXPECT_EQ(guard.adoptedEdits, 0u);
  EXPECT_EQ(toString(guard.byModel[1]),
            "stove.togglebutton: 12 -> 0 edits on 18 held-out points: adopted (stove judged as a "
            "whole: 12 -> 0 edits with the decisions adopted, noise 0.0 edits)");
  EXPECT_EQ(toJson(guard).at("models")[1].at("category_judged"), 2);
  const PointScorer adopted = adoptedScorer(&current, mixed, guard);
  EXPECT_TRUE(sameDecision(adopted.forModel("stove.togglebutton"), good));
  EXPECT_TRUE(sameDecision(adopted.forModel("stove.heatsource"), good));
  // What was adopted is what was judged: as the current scorer, its edits are the guard's.
  EXPECT_EQ(guardPointScorer(&adopted, mixed, heldOut, training).currentEdits, guard.adoptedEdits);

  // Both new decisions better: both adopted. Both as good as the current ones: neither (a tie
  // keeps the current decisions).
  better.byModel = {{"stove.togglebutton", good}, {"stove.heatsource", good}};
  current.byModel["stove.heatsource"] = poor;  // 24 edits before, none after
  const ScorerGuard both = guardPointScorer(&current, better, heldOut, training);
  EXPECT_TRUE(both.adoptedWhole());
  EXPECT_EQ(both.adoptedEdits, 0u);
  const ScorerGuard tie = guardPointScorer(&better, better, heldOut, training);
  EXPECT_FALSE(tie.adopted);
  EXPECT_EQ(tie.adoptedEdits, 0u);
}

TEST(PointScorerTraining, TheDecisionRecordsTheNetworkItsCandidatesCameFromAndRefusesAMix) {
  auto sets = syntheticSets();
  for (auto& s : sets) s.networkWeights = std::string(64, 'b');
  std::vector<const CandidateSet*> all;
  for (const auto& s : sets) all.push_back(&s);
  EXPECT_EQ(trainPointScorer(all, {}).forModel("stove.togglebutton")->networkWeights,
            std::string(64, 'b'));
  sets[4].networkWeights = std::string(64, 'c');
  try {
    trainPointScorer(all, {});
    FAIL() << "candidates of two networks were learned from as one";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(sets[4].object), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("different weights"), std::string::npos) << e.what();
  }
}

TEST(PointScorerTraining, AFeatureLeftOutIsZeroOnEveryCandidateAndAnUnknownOneIsNamed) {
  auto sets = syntheticSets();
  const std::size_t distance = candidateFeatureIndex("distance"),
                    height = candidateFeatureIndex("height");
  bool someNonZero = false;
  for (const auto& s : sets)
    for (const auto& c : s.candidates) someNonZero |= c.features[distance] != 0;
  ASSERT_TRUE(someNonZero);
  const auto before = sets;
  withoutFeatures(sets, {"distance"});
  for (std::size_t i = 0; i < sets.size(); ++i)
    for (std::size_t c = 0; c < sets[i].candidates.size(); ++c) {
      EXPECT_EQ(sets[i].candidates[c].features[distance], 0.0f);
      EXPECT_EQ(sets[i].candidates[c].features[height], before[i].candidates[c].features[height]);
    }
  // MODEL:FEATURE: that model's sets only.
  auto mixed = before;
  for (std::size_t i = 0; i < mixed.size(); i += 2) mixed[i].model = "stove.heatsource";
  withoutFeatures(mixed, {"stove.heatsource:height"});
  for (std::size_t i = 0; i < mixed.size(); ++i)
    for (std::size_t c = 0; c < mixed[i].candidates.size(); ++c)
      EXPECT_EQ(mixed[i].candidates[c].features[height],
                i % 2 == 0 ? 0.0f : before[i].candidates[c].features[height]);
  // A decision fitted without a feature for one model never reads it there.
  std::vector<const CandidateSet*> all;
  for (const auto& set : mixed) all.push_back(&set);
  const PointScorer scorer = trainPointScorer(all, {});
  for (const auto& tree : scorer.forModel("stove.heatsource")->classifier.trees->trees)
    for (const auto& node : tree) EXPECT_NE(node.feature, static_cast<int>(height));
  try {
    withoutFeatures(sets, {"stove.heatsource:no_such_feature"});
    FAIL() << "an unknown feature was left out";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_feature"), std::string::npos) << e.what();
  }
}

TEST(PointScorerTraining, CandidateFilesReadBackAndBadOnesAreNamed) {
  auto sets = syntheticSets();
  sets[0].networkWeights = std::string(64, 'd');
  ASSERT_GE(sets[0].candidates.size(), 2u);
  sets[0].candidates[0].copies = {1};
  sets[0].candidates[1].copies = {0};
  const auto file = std::filesystem::temp_directory_path() / "sagrid-candidates-test.json";
  writeCandidateSets(file, sets);
  const auto back = readCandidateSets(file);
  ASSERT_EQ(back.size(), sets.size());
  EXPECT_EQ(toJson(back).dump(), toJson(sets).dump());
  EXPECT_EQ(back[0].networkWeights, std::string(64, 'd'));
  EXPECT_EQ(back[0].candidates[1].copies, (std::vector<std::size_t>{0}));
  const auto refused = [&](nlohmann::json j, const std::string& why) {
    std::ofstream(file) << j.dump();
    try {
      readCandidateSets(file);
      ADD_FAILURE() << "read a file with " << why;
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
  };
  auto j = toJson(sets);
  j["features"][0] = "something_else";
  refused(j, "other features");
  j = toJson(sets);
  j["sets"][0].erase("copies");
  refused(j, "no copies (an older build's)");
  j = toJson(sets);
  j["sets"][0]["copies"][0] = {0};
  refused(j, "a candidate its own copy");
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace sagrid
