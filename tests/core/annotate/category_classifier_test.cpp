// The category classifier with rejection: separable synthetic classes, the file round-trip,
// corrupted files named in the error, ModelSet with and without category.json, and rejection of
// generated distractors by a tiny classifier trained on generated stoves, sinks and distractors.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <random>

#include "core/annotate/annotate.h"
#include "core/annotate/category_classifier.h"
#include "core/annotate/category_training.h"
#include "core/annotate/category_update.h"
#include "core/annotate/model_set.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/generate/dataset_generator.h"
#include "core/grid/top_relief.h"
#include "core/mesh/mesh.h"
#include "core/mesh/mesh_export.h"
#include "support/analytic_meshes.h"
#include "support/category_samples.h"
#include "support/test_paths.h"
#include "support/untrained_models.h"

namespace sagrid {
namespace {

// Three Gaussian blobs in 6-d, with a large shared nuisance dimension.
std::vector<CategorySample> blobs(int perClass, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, 0.2f), nuisance(0.0f, 50.0f);
  const std::vector<std::pair<std::string, std::vector<float>>> centres = {
      {"stove", {1, 0, 0, 0, 0}}, {"sink", {0, 1, 0, 0, 0}}, {"none", {0, 0, 1, 0, 0}}};
  std::vector<CategorySample> out;
  for (const auto& [cls, c] : centres)
    for (int i = 0; i < perClass; ++i) {
      CategorySample s;
      s.id = cls + std::to_string(i);
      s.category = cls == "none" ? "microwave" : cls;  // any other category is a distractor
      for (float v : c) s.descriptor.push_back(v + noise(rng));
      s.descriptor.push_back(nuisance(rng));
      out.push_back(s);
    }
  return out;
}

TEST(CategoryClassifier, SeparatesAndRejectsSyntheticClasses) {
  const auto train = blobs(30, 1), test = blobs(20, 2);
  const auto c = CategoryClassifier::train(train, {});
  ASSERT_EQ(c.classes(), (std::vector<std::string>{"sink", "stove", "none"}));
  int right = 0;
  for (const auto& s : test) right += c.classify(s.descriptor).category == categoryClass(s.category);
  EXPECT_GE(right, 57);  // of 60
  // A distractor is rejected but still says which category it resembles most.
  const auto d = c.classify({0.1f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f});
  EXPECT_TRUE(d.rejected);
  EXPECT_EQ(d.category, "none");
  EXPECT_FALSE(d.best.empty());
  // A threshold above every probability rejects everything.
  EXPECT_TRUE(c.classify({1, 0, 0, 0, 0, 0}, {}, 1.01).rejected);
  EXPECT_FALSE(c.classify({1, 0, 0, 0, 0, 0}, {}, 0.5).rejected);
  EXPECT_THROW(c.probabilities({1, 2}), InvalidArgument);
}

TEST(CategoryClassifier, FileRoundTripsAndCorruptionIsNamed) {
  auto c = CategoryClassifier::train(blobs(10, 3), {});
  c.featureBackend = "embedded";
  c.training["command"] = "test";
  const auto dir = test::freshTempDir();
  const auto file = dir / kCategoryClassifierFile;
  c.save(file);
  const auto back = CategoryClassifier::load(file);
  EXPECT_EQ(back.classes(), c.classes());
  EXPECT_EQ(back.featureBackend, "embedded");
  for (const auto& s : blobs(5, 4)) {
    const auto p = c.probabilities(s.descriptor), q = back.probabilities(s.descriptor);
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p[i], q[i], 1e-6);
  }
  // A changed number: the sha256 no longer matches.
  std::string text = readFileBytes(file);
  const auto at = text.find("\"threshold\": 0.5");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 16, "\"threshold\": 0.1");
  writeFileAtomic(file, text);
  try {
    CategoryClassifier::load(file);
    FAIL() << "edited file accepted";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("sha256"), std::string::npos) << e.what();
  }
  // Truncated: malformed JSON, also named.
  writeFileAtomic(file, readFileBytes(dir / kCategoryClassifierFile).substr(0, 100));
  try {
    CategoryClassifier::load(file);
    FAIL() << "truncated file accepted";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

// Boosted trees per class instead of the softmax: the same blobs separated and rejected, the
// probabilities a distribution, the file round-trips (trees, no weights) and a tree pointing
// outside itself is named.
TEST(CategoryClassifier, TreesSeparateSyntheticClassesAndRoundTrip) {
  CategoryTrainingOptions options;
  options.trees = true;
  options.boosting.depth = 2;
  const auto c = CategoryClassifier::train(blobs(30, 1), options);
  int right = 0;
  for (const auto& s : blobs(20, 2)) {
    right += c.classify(s.descriptor).category == categoryClass(s.category);
    const auto p = c.probabilities(s.descriptor);
    EXPECT_NEAR(p[0] + p[1] + p[2], 1.0, 1e-9);
  }
  EXPECT_GE(right, 57);  // of 60
  EXPECT_TRUE(c.classify({0.1f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f}).rejected);
  const auto dir = test::freshTempDir();
  const auto file = dir / kCategoryClassifierFile;
  c.save(file);
  const auto text = readFileBytes(file);
  EXPECT_NE(text.find("\"trees\""), std::string::npos);
  EXPECT_EQ(text.find("\"weights\""), std::string::npos);
  const auto back = CategoryClassifier::load(file);
  for (const auto& s : blobs(5, 4)) {
    const auto p = c.probabilities(s.descriptor), q = back.probabilities(s.descriptor);
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p[i], q[i], 1e-6);
  }
  auto j = nlohmann::json::parse(text);
  j["trees"][0]["trees"][0][0][0] = 999;  // a feature the inputs do not have
  j.erase("sha256");
  writeFileAtomic(file, j.dump());
  try {
    CategoryClassifier::load(file);
    FAIL() << "a broken tree was accepted";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

model::AffordanceModel cardOnly(const std::string& name, std::vector<float> mean) {
  std::vector<float> spread(mean.size(), 1.0f);
  return test::untrainedModelWithDescriptor(name, std::move(mean), std::move(spread));
}

ModelSet stoveAndSinkCards() {
  std::vector<model::AffordanceModel> models;
  models.push_back(cardOnly("stove.heatsource", {1, 0, 0, 0, 0, 0}));
  models.push_back(cardOnly("sink.fluidsource", {0, 1, 0, 0, 0, 0}));
  return ModelSet(std::move(models));
}

TEST(CategoryClassifier, ModelSetFallsBackToRetrievalWithoutAClassifier) {
  const ModelSet set = stoveAndSinkCards();
  EXPECT_EQ(set.categoryClassifier(), nullptr);
  // Retrieval never rejects: a distractor-like descriptor still gets a category.
  const auto d = set.decideCategory({0, 0, 1, 0, 0, 0});
  EXPECT_FALSE(d.rejected);
  EXPECT_NE(d.category, "none");
  EXPECT_EQ(set.decideCategory({1, 0, 0, 0, 0, 0}).category, "stove");
}

// Voxels of a footprint [10, 50)^2 on k = 0 whose columns top out at height(x, y) (64^3 grid).
std::vector<VoxelIndex> topOf(const std::function<int(int, int)>& height) {
  std::vector<VoxelIndex> out;
  for (int x = 10; x < 50; ++x)
    for (int y = 10; y < 50; ++y) out.insert(out.end(), {{x, y, 0}, {x, y, height(x, y)}});
  return out;
}
const std::vector<VoxelIndex> kFlatLid = topOf([](int, int) { return 30; });
const std::vector<VoxelIndex> kBasin =
    topOf([](int x, int y) { return x >= 20 && x < 40 && y >= 20 && y < 40 ? 15 : 30; });
const std::vector<VoxelIndex> kBurnerCaps = topOf([](int x, int y) {
  return (std::abs(x % 20 - 18) <= 1 && std::abs(y % 20 - 18) <= 1) ? 32 : 30;
});

// The stove and sink cards with a classifier trained on `samples`, saved and read back.
ModelSet withClassifierReadBack(const std::vector<CategorySample>& samples,
                                const CategoryTrainingOptions& options) {
  auto c = CategoryClassifier::train(samples, options);
  c.featureBackend = "embedded";
  const auto file = test::freshTempDir() / kCategoryClassifierFile;
  c.save(file);
  ModelSet set = stoveAndSinkCards();
  set.setCategoryClassifier(CategoryClassifier::load(file), file);
  return set;
}

// The descriptor says nothing (the same noise for every class); only the top tells them apart.
TEST(CategoryClassifier, TheTopReliefIsStoredAndReadWhenDeciding) {
  std::mt19937 rng(9);
  std::normal_distribution<float> noise(0.0f, 0.05f);
  std::vector<CategorySample> samples;
  const std::vector<std::pair<std::string, const std::vector<VoxelIndex>*>> shapes = {
      {"stove", &kBurnerCaps}, {"sink", &kBasin}, {"none", &kFlatLid}};
  for (const auto& [category, voxels] : shapes)
    for (int i = 0; i < 20; ++i) {
      std::vector<float> descriptor(6);
      for (float& v : descriptor) v = noise(rng);
      auto relief = topRelief(*voxels, 64);
      for (float& v : relief) v += noise(rng);
      ObjectDescriptor object;
      object.descriptor = descriptor;
      object.topRelief = relief;
      samples.push_back(test::categorySample(category + std::to_string(i), category, "test",
                                             categoryInputs(object, {true, false})));
    }
  CategoryTrainingOptions options;
  options.inputs.topRelief = true;
  const ModelSet set = withClassifierReadBack(samples, options);
  const CategoryClassifier& back = *set.categoryClassifier();
  EXPECT_TRUE(back.inputSet().topRelief);
  EXPECT_FALSE(back.inputSet().partStatistics);
  EXPECT_EQ(back.descriptorSize(), 6u + kTopReliefSize);
  EXPECT_TRUE(set.categoryInputSet().topRelief);
  const std::vector<float> quiet(6, 0.0f);
  EXPECT_THROW(set.decideCategory(quiet), InvalidArgument);  // the descriptor alone is not enough
  const auto withTop = [&](const std::vector<VoxelIndex>& voxels) {
    ObjectDescriptor object;
    object.descriptor = quiet;
    object.topRelief = topRelief(voxels, 64);
    return set.decideCategory(object);
  };
  EXPECT_EQ(withTop(kBurnerCaps).category, "stove");
  EXPECT_EQ(withTop(kBasin).category, "sink");
  EXPECT_TRUE(withTop(kFlatLid).rejected);
  // From an object's features: the relief of its voxels is appended.
  FeatureGrid grid;
  grid.resolution = 64;
  grid.descriptor = quiet;
  grid.voxels = kBasin;
  EXPECT_EQ(set.decideCategory(grid, Mesh{}).category, "sink");
  grid.voxels = kBurnerCaps;
  EXPECT_EQ(set.decideCategory(grid, Mesh{}).category, "stove");
}

// A counter 1 m x 0.6 m with `caps` equal flat squares 12 cm across standing on it.
Mesh counterWithCaps(int caps) {
  Mesh mesh = test::box({0, 0, 0}, {1.0f, 0.6f, 0.05f});
  for (int i = 0; i < caps; ++i) {
    const Eigen::Vector3f lo(0.1f + 0.2f * static_cast<float>(i), 0.2f, 0.05f);
    test::append(mesh, test::box(lo, lo + Eigen::Vector3f(0.12f, 0.12f, 0.02f)));
  }
  return mesh;
}

// The descriptor says nothing again; only the mesh's parts do: four caps a stove, one (a drain) a
// sink, none a look-alike.
TEST(CategoryClassifier, TheMeshsPartsAreStoredAndReadWhenDeciding) {
  std::mt19937 rng(11);
  std::normal_distribution<float> noise(0.0f, 0.02f);
  const std::vector<std::pair<std::string, int>> kinds = {{"stove", 4}, {"sink", 1}, {"none", 0}};
  std::vector<CategorySample> samples;
  for (const auto& [category, caps] : kinds)
    for (int i = 0; i < 20; ++i) {
      ObjectDescriptor object;
      object.descriptor.assign(6, 0.0f);
      for (float& v : object.descriptor) v = noise(rng);
      object.partStatistics = partStatistics(counterWithCaps(caps));
      for (float& v : object.partStatistics) v += noise(rng);
      samples.push_back(test::categorySample(category + std::to_string(i), category, "test",
                                             categoryInputs(object, {false, true})));
    }
  CategoryTrainingOptions options;
  options.inputs.partStatistics = true;
  options.trees = true;
  const ModelSet set = withClassifierReadBack(samples, options);
  EXPECT_TRUE(set.categoryInputSet().partStatistics);
  EXPECT_EQ(set.categoryClassifier()->descriptorSize(), 6u + kPartStatisticsSize);
  FeatureGrid grid;
  grid.descriptor.assign(6, 0.0f);
  EXPECT_EQ(set.decideCategory(grid, counterWithCaps(4)).category, "stove");
  EXPECT_EQ(set.decideCategory(grid, counterWithCaps(1)).category, "sink");
  EXPECT_TRUE(set.decideCategory(grid, counterWithCaps(0)).rejected);
  // A descriptor entry written without the parts cannot decide; one with them can.
  ObjectDescriptor entry;
  entry.descriptor = grid.descriptor;
  EXPECT_THROW(set.decideCategory(entry), InvalidArgument);
  entry.partStatistics = partStatistics(counterWithCaps(4));
  entry.hasPartStatistics = true;
  EXPECT_EQ(set.decideCategory(entry).category, "stove");
}

// The shape says nothing (the same noise for every class); the curated objects' file names do.
std::vector<CategorySample> namedByShapeAlike(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, 0.05f);
  const std::vector<std::pair<std::string, std::string>> kinds = {
      {"stove", "kitchenStove"}, {"sink", "bathroom_sink"}, {"none", "coffeeMachine"}};
  std::vector<CategorySample> samples;
  for (const auto& [category, name] : kinds)
    for (int i = 0; i < 20; ++i) {
      CategorySample s = test::categorySample(category + std::to_string(i), category, "test",
                                              {noise(rng), noise(rng), noise(rng)});
      s.nameWords = fileNameWords(name + std::to_string(i) + ".glb");
      s.publishedName = true;
      samples.push_back(s);
    }
  return samples;
}

TEST(CategoryClassifier, TheFileNamesWordsAreLearnedStoredAndReadWhenDeciding) {
  auto samples = namedByShapeAlike(13);
  // Generated objects are "mesh.glb" whatever their class: their name teaches nothing.
  for (int i = 0; i < 30; ++i) {
    CategorySample s = test::categorySample("gen" + std::to_string(i), "stove", "gen", {0, 0, 0});
    s.nameWords = fileNameWords("mesh.glb");
    samples.push_back(s);
  }
  CategoryTrainingOptions options;
  options.inputs.fileName = true;
  const ModelSet set = withClassifierReadBack(samples, options);
  const CategoryClassifier& c = *set.categoryClassifier();
  EXPECT_TRUE(c.inputSet().fileName);
  EXPECT_EQ(c.training.at("named_objects"), 60);
  std::vector<std::string> missing;  // a retrained classifier (the GUI's) counts names again
  EXPECT_TRUE(recipeOf(c, missing).options.inputs.fileName);
  FeatureGrid grid;
  grid.descriptor = {0, 0, 0};
  const Mesh mesh;
  const CategoryDecision stove = set.decideCategory(grid, mesh, nullptr, "in/my_stove.obj");
  EXPECT_EQ(stove.category, "stove");
  EXPECT_EQ(stove.nameWords, std::vector<std::string>{"stove"});  // what moved it, for a curator
  EXPECT_TRUE(set.decideCategory(grid, mesh, nullptr, "in/model.glb").nameWords.empty());
  const CategoryDecision sink = set.decideCategory(grid, mesh, nullptr, "in/Sink.glb");
  EXPECT_EQ(sink.category, "sink");
  EXPECT_TRUE(set.decideCategory(grid, mesh, nullptr, "in/coffee.glb").rejected);
  // Each decision says what the shape alone decided: here one category for all three names, so
  // the name decided at least one of them.
  const std::string byShape = c.classify(std::vector<float>{0, 0, 0}).category;
  EXPECT_EQ(stove.shapeCategory, byShape);
  EXPECT_EQ(sink.shapeCategory, byShape);
  EXPECT_TRUE(stove.category != byShape || sink.category != byShape);
  EXPECT_EQ(set.decideCategory(grid, mesh, nullptr, "in/model.glb").shapeCategory,
            set.decideCategory(grid, mesh, nullptr, "in/model.glb").category);
  // Unknown words and the generated objects' "mesh" leave the shape's probabilities as they are.
  EXPECT_EQ(c.probabilities({0, 0, 0}, fileNameWords("mesh.glb")), c.probabilities({0, 0, 0}));
  EXPECT_EQ(c.probabilities({0, 0, 0}, {"herd"}), c.probabilities({0, 0, 0}));
  // Without the input the same samples train a classifier that ignores names.
  const auto shapeOnly = CategoryClassifier::train(samples, {});
  EXPECT_FALSE(shapeOnly.inputSet().fileName);
  EXPECT_EQ(shapeOnly.probabilities({0, 0, 0}, {"stove"}), shapeOnly.probabilities({0, 0, 0}));
  // A file whose name evidence names other classes than the classifier is refused, named.
  const auto file = test::freshTempDir() / kCategoryClassifierFile;
  auto written = CategoryClassifier::train(samples, options);
  written.save(file);
  const auto good = nlohmann::json::parse(readFileBytes(file));
  const auto refusedNaming = [&](nlohmann::json j, const std::string& problem) {
    j.erase("sha256");
    writeFileAtomic(file, j.dump());
    try {
      CategoryClassifier::load(file);
      ADD_FAILURE() << "accepted: " << problem;
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos);
      EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
    }
  };
  auto otherClasses = good;
  otherClasses["file_name"]["classes"] = {"sink", "none", "stove"};
  refusedNaming(otherClasses, "file-name evidence");
  auto notCounts = good;
  notCounts["file_name"]["words"]["stove"] = "kitchen";
  refusedNaming(notCounts, "malformed name evidence");
  auto zero = good;
  zero["file_name"]["words"]["stove"]["kitchen"] = 0;
  refusedNaming(zero, "counted 0 times");
}

// The objects of namedByShapeAlike in three sources; where the names do not tell, each file is
// named for a class drawn regardless of its own.
std::vector<CategorySample> namedInThreeSources(bool namesTell) {
  auto samples = namedByShapeAlike(21);
  std::mt19937 rng(22);
  const std::vector<std::string> names = {"kitchenStove", "bathroom_sink", "coffeeMachine"};
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i].source = "repo-" + std::to_string(i % 3);
    if (!namesTell) samples[i].nameWords = fileNameWords(names[rng() % 3] + ".glb");
  }
  return samples;
}

// The names' weight beside the shape is learned from each source's objects decided without it:
// above the Bayes rule's 1 where every source names its files for what they hold (the shapes say
// nothing), below it where names are drawn regardless of the class; saved, read back and used.
TEST(CategoryClassifier, TheNamesWeightIsLearnedFromEachSourceDecidedWithoutIt) {
  CategoryTrainingOptions options;
  options.inputs.fileName = true;
  const auto samples = namedInThreeSources(true);
  const auto telling = CategoryClassifier::train(samples, options);
  const auto& fit = telling.training.at("file_name_weight");
  EXPECT_EQ(fit.at("sources"), 3);
  EXPECT_EQ(fit.at("held_out_objects"), 60);
  const double w = fit.at("weight").get<double>();
  EXPECT_GT(w, 1.0);
  EXPECT_GT(fit.at("log_likelihood").at("fitted").get<double>(),
            fit.at("log_likelihood").at("bayes_rule").get<double>());
  // Deciding, two classes' log odds move by w times their words' log-likelihood difference.
  std::vector<std::pair<std::vector<std::string>, std::string>> named;
  for (const auto& s : samples) named.emplace_back(s.nameWords, s.category);
  const auto ll = NameEvidence::count(named, telling.classes()).logLikelihoods({"stove"});
  const auto shape = telling.probabilities({0, 0, 0});
  const auto withName = telling.probabilities({0, 0, 0}, {"stove"});
  const auto logOdds = [](const std::vector<double>& p) { return std::log(p[1] / p[2]); };
  ASSERT_EQ(telling.classes(), (std::vector<std::string>{"sink", "stove", "none"}));
  EXPECT_NEAR(logOdds(withName) - logOdds(shape), w * (ll[1] - ll[2]), 1e-9);
  const auto file = test::freshTempDir() / kCategoryClassifierFile;
  telling.save(file);
  EXPECT_EQ(CategoryClassifier::load(file).probabilities({0, 0, 0}, {"stove"}), withName);

  // Retrained (the guard's recipe, the GUI's Train panel), a fitted weight is fitted again, a
  // fixed one kept, and a file that read names before the weight was learned keeps the Bayes rule.
  std::vector<std::string> missing;
  EXPECT_FALSE(recipeOf(telling, missing).options.nameWeight);
  CategoryTrainingOptions fixed = options;
  fixed.nameWeight = 0.5;
  EXPECT_EQ(recipeOf(CategoryClassifier::train(samples, fixed), missing).options.nameWeight, 0.5);
  CategoryClassifier before = telling;
  before.training.erase("file_name_weight");
  EXPECT_EQ(recipeOf(before, missing).options.nameWeight, 1.0);

  const auto drawn = CategoryClassifier::train(namedInThreeSources(false), options);
  EXPECT_LT(drawn.training.at("file_name_weight").at("weight").get<double>(), 1.0);
  // Names of one source only: nothing to hold out, the Bayes rule.
  auto oneSource = samples;
  for (auto& s : oneSource) s.source = "repo-0";
  const auto single = CategoryClassifier::train(oneSource, options);
  EXPECT_EQ(single.training.at("file_name_weight").at("weight"), 1.0);
  EXPECT_EQ(single.training.at("file_name_weight").at("held_out_objects"), 0);
  // One source holds every stove: left out, the others teach no stove; the others left out, the
  // stoves teach one class. Nothing can be held out, and training goes on with the Bayes rule.
  auto lopsided = samples;
  for (auto& s : lopsided) s.source = s.category == "stove" ? "stoves" : "the rest";
  const auto apart = CategoryClassifier::train(lopsided, options);
  EXPECT_EQ(apart.training.at("file_name_weight").at("weight"), 1.0);
  EXPECT_EQ(apart.training.at("file_name_weight").at("held_out_objects"), 0);
}

TEST(CategoryClassifier, ModelSetUsesTheClassifierAndChecksIt) {
  ModelSet set = stoveAndSinkCards();
  auto c = CategoryClassifier::train(blobs(20, 5), {});
  c.featureBackend = "embedded";
  set.setCategoryClassifier(c, "category.json");
  ASSERT_NE(set.categoryClassifier(), nullptr);
  EXPECT_EQ(set.decideCategory({0, 0, 1, 0, 0, 0}).category, "none");
  EXPECT_EQ(set.decideCategory({1, 0, 0, 0, 0, 0}).category, "stove");
  // Other features than the cards: refused, naming the file.
  ModelSet other = stoveAndSinkCards();
  c.featureBackend = "dinov2";
  try {
    other.setCategoryClassifier(c, "models/category.json");
    FAIL() << "classifier of other features accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("models/category.json"), std::string::npos);
  }
}

// Cheap features for generated objects (the real pipeline at a small grid and few views).
std::vector<float> descriptorOf(const gen::FinishedObject& o) {
  FeatureOptions f;
  f.resolution = 32;
  f.views = 24;
  f.renderSize = 48;
  return computeFeatures(o.mesh, f).descriptor;
}

TEST(CategoryClassifier, RejectsGeneratedDistractors) {
  std::vector<CategorySample> train, test;
  const std::vector<std::pair<std::string, std::uint64_t>> sets = {
      {"stove", 91}, {"sink", 92}, {"none", 93}};
  for (const auto& [category, seed] : sets)
    for (int i = 0; i < 40; ++i) {
      const auto o = gen::makeObject(category, seed, i, gen::MeshFormat::Obj);
      (i < 30 ? train : test)
          .push_back(test::categorySample(o.id, category, category, descriptorOf(o)));
    }
  CategoryTrainingOptions options;
  options.l2 = 0.1;  // 90 objects for 64 dimensions: keep the weights small
  const auto c = CategoryClassifier::train(train, options);
  const auto ev =
      evaluateCategories([&](const CategorySample& s) { return c.classify(s.descriptor); }, test);
  // 10 held-out objects per class; a distractor counts as right only when rejected.
  EXPECT_GE(ev.byClass.at("none").right, 8) << categoryEvaluationTable(ev);
  // Cheap features and 30 objects per class: well above chance (1/3), not the real figure.
  EXPECT_GE(ev.byClass.at("stove").right + ev.byClass.at("sink").right, 12)
      << categoryEvaluationTable(ev);
}

TEST(CategoryEvaluation, ListsTheObjectsDecidedWrongly) {
  // A rule by the descriptor's first value: > 0.5 stove, else rejected (best: sink).
  auto decide = [](const CategorySample& s) {
    const auto& d = s.descriptor;
    CategoryDecision r;
    r.best = d[0] > 0.5f ? "stove" : "sink";
    r.score = d[0];
    r.rejected = d[0] <= 0.5f;
    r.category = r.rejected ? std::string(kRejectedCategory) : r.best;
    return r;
  };
  const std::vector<CategorySample> samples = {
      test::categorySample("gas_stove", "stove", "real", {0.9f}),
      test::categorySample("camping_stove", "stove", "real", {0.2f}),
      test::categorySample("oven", "none", "real", {0.7f}),
      test::categorySample("fridge", "none", "real", {0.1f})};
  const auto ev = evaluateCategories(decide, samples);
  ASSERT_EQ(ev.misses.size(), 2u);
  EXPECT_EQ(ev.misses[0].id, "camping_stove");
  EXPECT_EQ(ev.misses[0].predicted, "none");
  EXPECT_EQ(ev.misses[0].best, "sink");
  EXPECT_EQ(ev.misses[1].id, "oven");
  EXPECT_EQ(ev.misses[1].truth, "none");
  EXPECT_EQ(ev.misses[1].predicted, "stove");
  const std::string table = categoryEvaluationTable(ev);
  EXPECT_NE(table.find("| camping_stove | real | stove | none | sink (0.20) |"), std::string::npos)
      << table;
  EXPECT_NE(table.find("| oven | real | none | stove | stove (0.70) |"), std::string::npos)
      << table;
  EXPECT_EQ(table.find("gas_stove"), std::string::npos) << table;
}

// The category guard's rule: two thresholds decide the same objects; each class counts alike and
// the candidate wins only beyond the standard error of the per-object differences.
TEST(CategoryEvaluation, PairsTwoClassifiersObjectByObject) {
  const auto threshold = [](float t) {
    return [t](const CategorySample& s) {
      CategoryDecision r;
      r.best = "stove";
      r.score = s.descriptor[0];
      r.rejected = s.descriptor[0] <= t;
      r.category = r.rejected ? std::string(kRejectedCategory) : r.best;
      return r;
    };
  };
  std::vector<CategorySample> samples;
  for (float d : {0.9f, 0.8f, 0.45f, 0.4f, 0.35f})
    samples.push_back(test::categorySample("stove" + std::to_string(d), "stove", "real", {d}));
  for (float d : {0.1f, 0.2f, 0.3f})
    samples.push_back(test::categorySample("oven" + std::to_string(d), "none", "real", {d}));
  const auto current = evaluateCategories(threshold(0.5f), samples);  // stoves 2/5, ovens 3/3
  const auto all = evaluateCategories(threshold(0.33f), samples);     // stoves 5/5
  const auto one = evaluateCategories(threshold(0.42f), samples);     // stoves 3/5
  const PairedChange fixesThree = pairedCategoryChange(current, all);
  EXPECT_EQ(fixesThree.objects, 8u);
  EXPECT_NEAR(1 - fixesThree.current, balancedShareRight(current), 1e-12);  // 0.7
  EXPECT_NEAR(1 - fixesThree.candidate, balancedShareRight(all), 1e-12);    // 1.0
  // Stoves' differences -1, -1, -1, 0, 0 (variance 0.3), ovens' none; halved as two classes.
  EXPECT_NEAR(fixesThree.noise, std::sqrt(0.3 / 5) / 2, 1e-12);
  EXPECT_TRUE(fixesThree.clearlyBetter());
  // One stove of five fixed is as likely noise.
  const PairedChange fixesOne = pairedCategoryChange(current, one);
  EXPECT_NEAR(fixesOne.change(), -0.1, 1e-12);
  EXPECT_FALSE(fixesOne.clearlyBetter());
  EXPECT_FALSE(pairedCategoryChange(all, current).clearlyBetter());
}

TEST(CategoryClassifier, AnnotateWritesNoneAndNoPointsForARejectedObject) {
  // A distractor on disk, and models whose classifier rejects everything (threshold above any
  // probability): annotate must not ask any model for points.
  const auto dir = test::freshTempDir();
  auto object = gen::makeObject("none", 5, 0, gen::MeshFormat::Obj);
  writeEncodedMeshFiles(encodeObj(object.mesh, "old_toaster"), dir);
  std::vector<model::AffordanceModel> models;
  models.push_back(cardOnly("stove.heatsource", std::vector<float>(64, 0.1f)));
  models.push_back(cardOnly("sink.fluidsource", std::vector<float>(64, 0.2f)));
  ModelSet set(std::move(models));
  std::vector<CategorySample> samples;
  for (int i = 0; i < 6; ++i)
    samples.push_back(test::categorySample("s" + std::to_string(i),
                                           i % 3 == 0   ? "stove"
                                           : i % 3 == 1 ? "sink"
                                                        : "none",
                                           "", std::vector<float>(64, static_cast<float>(i))));
  for (auto& s : samples) {  // names too: the words that moved the decision are recorded
    s.nameWords = {s.category == "none" ? "toaster" : s.category};
    s.publishedName = true;
  }
  CategoryTrainingOptions withNames;
  withNames.inputs.fileName = true;
  auto classifier = CategoryClassifier::train(samples, withNames);
  classifier.featureBackend = "embedded";
  classifier.setThreshold(1.01);
  set.setCategoryClassifier(classifier, "category.json");
  AnnotateOptions options;
  options.features.resolution = 32;
  options.features.views = 12;
  options.features.renderSize = 32;
  options.suggestions = false;  // the card-only models cannot predict suggestions
  const auto r = annotateMeshFile(dir / "old_toaster.obj", "d", set, options, dir);
  EXPECT_TRUE(r.rejected);
  EXPECT_EQ(r.categoryNameWords, std::vector<std::string>{"toaster"});
  EXPECT_EQ(r.labels.extra.at("prediction").at("category_name_words"),
            nlohmann::json::array({"toaster"}));
  options.readFileName = false;  // `annotate --no-file-name`: the shape alone
  const auto shapeOnly = annotateMeshFile(dir / "old_toaster.obj", "d", set, options, dir);
  EXPECT_TRUE(shapeOnly.categoryNameWords.empty());
  EXPECT_FALSE(shapeOnly.labels.extra.at("prediction").contains("category_name_words"));
  EXPECT_EQ(r.category, "none");
  EXPECT_EQ(r.labels.object.category, "none");
  EXPECT_TRUE(r.labels.affordances.empty());
  EXPECT_TRUE(r.predictions.empty());
  EXPECT_FALSE(r.closestCategory.empty());
}

// The shipped resources/models/category.json with the shipped cards, on generated distractors of
// a seed no split uses, at the full feature setup (about a second each).
TEST(CategoryClassifier, ShippedClassifierRejectsGeneratedDistractorsSlow) {
  const ModelSet set = ModelSet::load(std::filesystem::path(SAGRID_SOURCE_DIR) / "resources" / "models");
  ASSERT_NE(set.categoryClassifier(), nullptr);
  int rejected = 0;
  const int n = 8;
  for (int i = 0; i < n; ++i) {
    const auto o = gen::makeObject("none", 777, i, gen::MeshFormat::Obj);
    rejected += set.decideCategory(computeFeatures(o.mesh, set.featureOptions()), o.mesh).rejected;
  }
  EXPECT_GE(rejected, n - 1);
  // A generated stove is not rejected.
  const auto stove = gen::makeObject("stove", 777, 0, gen::MeshFormat::Obj);
  EXPECT_EQ(
      set.decideCategory(computeFeatures(stove.mesh, set.featureOptions()), stove.mesh).category,
      "stove");
}

// The shipped classifier (and the evidence gate where the file carries one; the shipped file
// carries none since session 33), as `annotate` without --category meets them, on the bundled
// samples a user opens first: every one filed under its category (the folder name's prefix).
TEST(CategoryClassifier, ShippedModelsFileEveryBundledSampleUnderItsCategorySlow) {
  const auto resources = std::filesystem::path(SAGRID_SOURCE_DIR) / "resources";
  const ModelSet set = ModelSet::load(resources / "models");
  ASSERT_NE(set.categoryClassifier(), nullptr);
  int samples = 0;
  for (const auto& folder : std::filesystem::directory_iterator(resources / "samples")) {
    if (!folder.is_directory()) continue;
    const std::string id = folder.path().filename().string();
    const auto glb = folder.path() / "mesh.glb";
    const auto mesh = std::filesystem::exists(glb) ? glb : folder.path() / "mesh.obj";
    const auto r = annotateMeshFile(mesh, id, set, {}, test::freshTempDir());
    EXPECT_EQ(r.category, id.substr(0, id.find('_')))
        << id << " (closest " << r.closestCategory << ")";
    ++samples;
  }
  EXPECT_EQ(samples, 6);
}

}  // namespace
}  // namespace sagrid
