// K-fold cross-validation of the category classifier: balanced deterministic folds, every
// validated object decided once and never by a classifier that saw it, the other folds teaching
// the held-out one, and clear errors for impossible fold counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include "core/annotate/category_cross_validation.h"
#include "core/common/error.h"

namespace sagrid {
namespace {

CategorySample sample(const std::string& id, const std::string& category, float x, float y,
                      const std::string& group) {
  CategorySample s;
  s.id = id;
  s.category = category;
  s.group = group;
  s.descriptor = {x, y};
  return s;
}

// Generated-like samples: stoves around (2, 0), sinks around (-2, 0), distractors around (0, 2).
std::vector<CategorySample> generated(int perClass) {
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0.0f, 0.3f);
  std::vector<CategorySample> out;
  for (int i = 0; i < perClass; ++i) {
    out.push_back(sample("gs" + std::to_string(i), "stove", 2 + noise(rng), noise(rng), "gen"));
    out.push_back(sample("gk" + std::to_string(i), "sink", -2 + noise(rng), noise(rng), "gen"));
    out.push_back(sample("gn" + std::to_string(i), "none", noise(rng), 2 + noise(rng), "gen"));
  }
  return out;
}

CategoryTrainingOptions quick() {
  CategoryTrainingOptions options;
  options.iterations = 3000;
  return options;
}

TEST(CategoryCrossValidation, FoldsAreBalancedAndIndependentOfOrder) {
  std::vector<std::string> ids;
  for (int i = 0; i < 23; ++i) ids.push_back("object" + std::to_string(i));
  const auto folds = assignFolds(ids, 5);
  std::vector<int> sizes(5, 0);
  for (const auto& [id, k] : folds) ++sizes.at(static_cast<std::size_t>(k));
  EXPECT_EQ(
      *std::max_element(sizes.begin(), sizes.end()) - *std::min_element(sizes.begin(), sizes.end()),
      1);
  std::reverse(ids.begin(), ids.end());
  EXPECT_EQ(assignFolds(ids, 5), folds);
}

TEST(CategoryCrossValidation, TheTrainValSplitIsTheThirdOfThreeFolds) {
  std::vector<std::string> ids;
  for (int i = 0; i < 30; ++i) ids.push_back("object" + std::to_string(i));
  const IdSplit split = splitIds(ids);
  EXPECT_EQ(split.val.size(), 10u);
  EXPECT_EQ(split.train.size(), 20u);
  for (const auto& [id, fold] : assignFolds(ids, 3))
    EXPECT_EQ(split.val.count(id), fold == 2 ? 1u : 0u);
  std::reverse(ids.begin(), ids.end());
  EXPECT_EQ(splitIds(ids).val, split.val);
}

TEST(CategoryCrossValidation, TheOtherFoldsTeachEachHeldOutObject) {
  // Real stoves look like nothing generated (around (0, -2)): trained on the generated samples
  // alone, they are not called stoves; each is right when the other real stoves train.
  std::vector<CategorySample> real;
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(0.0f, 0.2f);
  for (int i = 0; i < 10; ++i)
    real.push_back(
        sample("real" + std::to_string(i), "stove", noise(rng), -2 + noise(rng), "real"));
  const auto always = generated(20);
  const auto alone = CategoryClassifier::train(always, quick());
  int rightAlone = 0;
  for (const auto& s : real) rightAlone += alone.classify(s.descriptor).category == "stove";
  EXPECT_LT(rightAlone, 5);

  const auto ev = crossValidateCategories(always, real, 5, quick());
  EXPECT_EQ(ev.byClass.at("stove").total, 10);  // each decided once
  EXPECT_EQ(ev.byClass.at("stove").right, 10);
  EXPECT_TRUE(ev.misses.empty());
}

TEST(CategoryCrossValidation, ObjectsOfWeightZeroAreDecidedButNeverTrainedOn) {
  // The real stoves of TheOtherFoldsTeachEachHeldOutObject, which teach each other when trained
  // on: at weight 0 (a recipe that does not learn from them) each is decided as by the generated
  // samples alone.
  std::vector<CategorySample> real;
  for (int i = 0; i < 10; ++i) {
    real.push_back(
        sample("real" + std::to_string(i), "stove", 0.02f * static_cast<float>(i), -2, "real"));
    real.back().weight = 0;
  }
  const auto always = generated(20);
  const auto alone = CategoryClassifier::train(always, quick());
  int rightAlone = 0;
  for (const auto& s : real) rightAlone += alone.classify(s.descriptor).category == "stove";
  const auto ev = crossValidateCategories(always, real, 5, quick());
  EXPECT_EQ(ev.byClass.at("stove").total, 10);
  EXPECT_EQ(ev.byClass.at("stove").right, rightAlone);
  EXPECT_LT(rightAlone, 5);
}

TEST(CategoryCrossValidation, AnObjectIsNeverDecidedByAClassifierThatSawIt) {
  // A sink that looks exactly like a stove, weighed heavily: a classifier trained on it would
  // learn it, one trained without it calls it a stove.
  auto real = std::vector<CategorySample>{sample("odd", "sink", 2, 0, "real")};
  real.front().weight = 200;
  for (int i = 0; i < 4; ++i)
    real.push_back(
        sample("k" + std::to_string(i), "sink", -2, 0.1f * static_cast<float>(i), "real"));
  const auto always = generated(10);
  auto seen = always;
  seen.push_back(real.front());
  EXPECT_EQ(CategoryClassifier::train(seen, quick()).classify({2, 0}).category, "sink");

  const auto ev = crossValidateCategories(always, real, 5, quick());
  ASSERT_EQ(ev.misses.size(), 1u);
  EXPECT_EQ(ev.misses.front().id, "odd");
  EXPECT_EQ(ev.misses.front().predicted, "stove");
  EXPECT_EQ(ev.byGroup.at("real (sink)").total, 5);
}

TEST(CategoryCrossValidation, ImpossibleFoldsAreClearErrors) {
  const auto always = generated(5);
  const std::vector<CategorySample> two{sample("a", "stove", 2, 0, "r"),
                                        sample("b", "sink", -2, 0, "r")};
  EXPECT_THROW(crossValidateCategories(always, two, 1, quick()), InvalidArgument);
  EXPECT_THROW(crossValidateCategories(always, two, 3, quick()), InvalidArgument);
  const std::vector<CategorySample> twice{sample("a", "stove", 2, 0, "r"),
                                          sample("a", "sink", -2, 0, "r")};
  EXPECT_THROW(crossValidateCategories(always, twice, 2, quick()), InvalidArgument);
}

}  // namespace
}  // namespace sagrid

namespace sagrid {
namespace {

// Leave one source out: each source is one fold, held out whole; a source that only its own
// objects explain (a repository whose stoves sit apart) is decided by classifiers that never saw it.
TEST(CategoryCrossValidationBySource, EachSourceIsHeldOutWhole) {
  std::vector<CategorySample> validated;
  for (int i = 0; i < 4; ++i) {
    for (const char* source : {"repo/a", "repo/b", "library/c"}) {
      CategorySample s = sample(std::string(source) + std::to_string(i), i % 2 ? "stove" : "sink",
                                i % 2 ? 2.0f : -2.0f, 0.1f * static_cast<float>(i), "real");
      s.source = source;
      validated.push_back(s);
    }
  }
  std::vector<std::set<std::string>> heldSources;
  int folds = 0;
  const CategoryEvaluation ev = crossValidateCategoriesBySource(
      generated(20), validated, quick(),
      [&](int, int n) {
        folds = n;
        heldSources.emplace_back();
      },
      [&](const CategorySample& s, const CategoryDecision& d) {
        heldSources.back().insert(s.source);
        return d;
      });
  EXPECT_EQ(folds, 3);
  ASSERT_EQ(heldSources.size(), 3u);
  for (const auto& held : heldSources) EXPECT_EQ(held.size(), 1u);  // one source per fold
  EXPECT_EQ(ev.byClass.at("stove").total + ev.byClass.at("sink").total, 12);

  for (auto& s : validated) s.source = "one";
  EXPECT_THROW(crossValidateCategoriesBySource(generated(5), validated, quick()), InvalidArgument);
}

// The names too are learned without the held-out source: a word only its objects' names hold
// says nothing of them, one another source's names hold does.
TEST(CategoryCrossValidationBySource, AHeldOutSourcesNamesTeachNothingOfIt) {
  std::vector<CategorySample> validated;
  const auto named = [&](const std::string& source, const std::string& category,
                         const std::string& name, int i) {
    CategorySample s = sagrid::sample(source + std::to_string(i), category, 0.0f, 0.0f, "real");
    s.source = source;
    s.nameWords = {name};
    s.publishedName = true;
    validated.push_back(s);
  };
  for (int i = 0; i < 4; ++i) {
    named("repo/a", "stove", "herd", i);
    named("repo/b", "stove", "herd", i);
    named("library/c", "sink", "lavello", i);
    named("library/d", "none", "kettle", i);
  }
  CategoryTrainingOptions options = quick();
  options.inputs.fileName = true;
  std::map<std::string, CategoryDecision> withNames, shapeOnly;
  const auto keep = [](std::map<std::string, CategoryDecision>& into) {
    return [&into](const CategorySample& s, const CategoryDecision& d) {
      into[s.id] = d;
      return d;
    };
  };
  crossValidateCategoriesBySource(generated(20), validated, options, {}, keep(withNames));
  crossValidateCategoriesBySource(generated(20), validated, quick(), {}, keep(shapeOnly));
  for (int i = 0; i < 4; ++i) {
    const std::string k = std::to_string(i);
    // "herd" is learned from the other stove source.
    EXPECT_EQ(withNames.at("repo/a" + k).category, "stove");
    EXPECT_GT(withNames.at("repo/a" + k).score, shapeOnly.at("repo/a" + k).score);
    // "lavello" and "kettle" only ever named objects of the source held out.
    for (const std::string& id : {"library/c" + k, "library/d" + k}) {
      EXPECT_EQ(withNames.at(id).category, shapeOnly.at(id).category) << id;
      EXPECT_DOUBLE_EQ(withNames.at(id).score, shapeOnly.at(id).score) << id;
    }
  }
}

}  // namespace
}  // namespace sagrid
