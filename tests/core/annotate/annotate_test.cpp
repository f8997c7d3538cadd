#include "core/annotate/annotate.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/annotate/annotation_fingerprint.h"
#include "core/annotate/category_evidence.h"
#include "core/annotate/suggested_points.h"
#include "core/annotate/units_record.h"
#include "core/common/error.h"
#include "core/dataset/dataset.h"
#include "core/eval/evaluation.h"
#include "core/features/feature_grid.h"
#include "core/generate/dataset_generator.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh_import.h"
#include "support/category_samples.h"
#include "support/import_errors.h"
#include "support/test_paths.h"
#include "support/untrained_models.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;

class AnnotateTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::freshTempDir();
    gen::generateDataset({{"stove", 1, 5}, {"sink", 1, 5}}, gen::MeshFormat::Glb, dir / "data");
    entries = readDataset(dir / "data");
    ASSERT_EQ(entries.size(), 2u);
    FeatureOptions options;
    options.views = 12;
    stoveFeatures = extractFeatures(entries[0].mesh, options);
    sinkFeatures = extractFeatures(entries[1].mesh, options);
    std::vector<model::AffordanceModel> models;
    models.push_back(test::untrainedModelFor("stove.heatsource", stoveFeatures));
    models.push_back(test::untrainedModelFor("stove.togglebutton", stoveFeatures));
    models.push_back(test::untrainedModelFor("sink.fluidsource", sinkFeatures));
    set = std::make_unique<ModelSet>(std::move(models));
    annotate.features = options;
  }
  fs::path dir;
  std::vector<DatasetEntry> entries;
  FeatureGrid stoveFeatures, sinkFeatures;
  std::unique_ptr<ModelSet> set;
  AnnotateOptions annotate;
};

TEST_F(AnnotateTest, PredictsEveryModelOfTheRetrievedCategoryOnTheSurface) {
  const AnnotationResult r =
      annotateMeshFile(entries[0].mesh, "stove0", *set, annotate, dir / "out" / "stove0");
  EXPECT_EQ(r.category, "stove");  // retrieval: its own descriptor is the stove mean
  EXPECT_TRUE(r.categoryRetrieved);
  EXPECT_NEAR(r.categorySimilarity, 1.0, 1e-6);
  ASSERT_EQ(r.predictions.size(), 2u);
  EXPECT_EQ(r.labels.object.category, "stove");
  EXPECT_EQ(r.labels.object.up, "y");
  EXPECT_EQ(r.labels.object.mesh,
            "../../data/" + entries[0].mesh.parent_path().filename().string() + "/mesh.glb");
  ASSERT_FALSE(r.labels.affordances.empty());
  const Mesh mesh = importMesh(entries[0].mesh);
  const SurfaceScene scene(mesh);
  for (const auto& a : r.labels.affordances) {
    EXPECT_THAT(a.source, HasSubstr("stove."));
    EXPECT_THAT(a.source, HasSubstr("@"));
    ASSERT_TRUE(a.confidence.has_value());
    EXPECT_GT(*a.confidence, 0.0f);
    EXPECT_LE(*a.confidence, 1.0f);
    // Written in the file's (y-up) frame and on the surface.
    const ClosestPoint c = scene.closestPoint(fileToZUp(a.position, UpAxis::Y));
    EXPECT_LT(c.distance, 1e-4f * mesh.bounds().diagonal().norm());
    ASSERT_TRUE(a.normal.has_value());
    EXPECT_NEAR(a.normal->norm(), 1.0f, 1e-4f);
  }
}

TEST_F(AnnotateTest, EvalMeasuresThePointsAnnotateWritesWithTheSamePasses) {
  // Both run core/annotate/point_passes: with the same (non-default) pass options, eval's
  // automatic-count points are annotate's, point for point.
  PassOptions passes;
  passes.symmetries = 2;
  passes.learnedDecision = false;
  passes.coarseToFine = true;
  static_cast<PassOptions&>(annotate) = passes;
  annotate.category = "stove";
  const AnnotationResult r =
      annotateMeshFile(entries[0].mesh, "stove0", *set, annotate, dir / "out" / "stove0");
  EvaluationOptions eval;
  static_cast<PassOptions&>(eval) = passes;
  eval.dataDir = dir / "data";
  eval.features = annotate.features;
  const EvaluationReport report = evaluateModels(*set, eval);
  std::size_t compared = 0;
  for (const auto& object : report.perObject) {
    if (object.at("category") != "stove") continue;
    for (const auto& [model, byMethod] : object.at("predictions").items()) {
      const std::string type = model.substr(model.find('.') + 1);
      std::vector<Eigen::Vector3f> written;
      for (const auto& a : r.labels.affordances)
        if (a.type == type) written.push_back(a.position);
      const auto& measured = byMethod.at("SAGrid auto count");
      ASSERT_EQ(measured.size(), written.size()) << model;
      for (std::size_t i = 0; i < written.size(); ++i, ++compared)
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(measured[i][k].get<float>(), written[i][k], 1e-5f) << model << " point " << i;
    }
  }
  EXPECT_GT(compared, 0u);
}

TEST_F(AnnotateTest, EvalCoversTheUnionOfEveryDatasetGiven) {
  gen::generateDataset({{"sink", 2, 7}}, gen::MeshFormat::Glb, dir / "more");
  EvaluationOptions eval;
  eval.symmetries = 1;
  eval.dataDir = dir / "data";
  eval.moreData = {dir / "more"};
  eval.features = annotate.features;
  const EvaluationReport report = evaluateModels(*set, eval);
  EXPECT_EQ(report.objects, 4u);  // a stove and a sink, and two more sinks
  EXPECT_EQ(report.perObject.size(), 4u);
  EXPECT_EQ(report.confidenceSignal.size(), 4u);
  // Each generated object carries its generator settings (for the count breakdown by setting).
  for (const auto& object : report.perObject)
    EXPECT_TRUE(object.contains("generator") && object.at("generator").contains("kind"))
        << object.dump();
  EXPECT_EQ(evaluatedData(report), (dir / "data").string() + " + " + (dir / "more").string());
  // Generated objects carry no provenance: each dataset folder is a source of its own.
  ASSERT_EQ(report.bySource.size(), 2u);
  EXPECT_EQ(report.bySource.at("data").effort.objects, 2u);
  EXPECT_EQ(report.bySource.at("more").effort.objects, 2u);
  EXPECT_THAT(evaluationMarkdown(report), HasSubstr("## By source"));
  EXPECT_THAT(evaluationMarkdown(report), HasSubstr(evaluatedData(report)));
  // Each dataset read its features from its own cache.
  EXPECT_TRUE(fs::is_directory(dir / "more" / ".sagrid-cache"));
  eval.moreData = {dir / "missing"};
  try {
    evaluateModels(*set, eval);
    FAIL() << "a missing dataset must be an error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("missing"));
  }
}

TEST_F(AnnotateTest, WritesTheObjectConfidenceOfTheLeastSurePoint) {
  annotate.category = "stove";
  annotate.confidence.fitted = true;
  annotate.confidence.intercept = 1.0;
  annotate.confidence.slope = -0.5;
  const AnnotationResult r = annotateMeshFile(entries[0].mesh, "s", *set, annotate, dir);
  const double expected = annotate.confidence.probability(leastSurePointDistance(r.predictions));
  EXPECT_DOUBLE_EQ(r.objectConfidence, expected);
  EXPECT_DOUBLE_EQ(r.labels.extra["prediction"]["object_confidence"].get<double>(), expected);
  EXPECT_TRUE(r.labels.extra["prediction"]["object_confidence_calibrated"].get<bool>());
}

TEST_F(AnnotateTest, AFolderRememberingSizesScalesAFileFarFromObjectsLikeIt) {
  annotate.category = "stove";
  const double extent = importMesh(entries[0].mesh).bounds().sizes().maxCoeff();
  const AnnotationResult named = annotateMeshFile(entries[0].mesh, "s", *set, annotate, dir);
  const auto namedGuess = recordedUnitGuess(named.labels.object);
  ASSERT_TRUE(namedGuess);
  // Curated stoves that look exactly like it are 20 times the size its named unit gives.
  const double remembered = 20.0 * extent * namedGuess->metersPerUnit;
  RememberedSize curated;
  curated.id = "curated";
  curated.source = "elsewhere";
  curated.category = "stove";
  curated.descriptor = stoveFeatures.descriptor;
  curated.units.largestExtent = remembered;
  curated.metersPerUnit = 1.0;
  set->setSizeMemory(SizeMemory({curated},
                                set->models().front().card().featureConfigHash, 4.0),
                     dir / kSizeMemoryFile);
  const AnnotationResult r = annotateMeshFile(entries[0].mesh, "s", *set, annotate, dir);
  const auto guess = recordedUnitGuess(r.labels.object);
  ASSERT_TRUE(guess);
  EXPECT_NEAR(guess->metersPerUnit * extent, remembered, 1e-6 * remembered);
  EXPECT_NE(guess->reason.find("curated objects like it"), std::string::npos) << guess->reason;
  // A memory made with other features is refused, naming its file.
  try {
    set->setSizeMemory(SizeMemory({}, "other-features", 4.0), dir / kSizeMemoryFile);
    ADD_FAILURE() << "a memory of other features was taken";
  } catch (const ModelError& e) {
    EXPECT_THAT(e.what(), HasSubstr(kSizeMemoryFile));
  }
}

TEST_F(AnnotateTest, SymmetryAveragingKeepsThePointsOnTheSurface) {
  annotate.category = "stove";
  annotate.symmetries = 8;
  const AnnotationResult r = annotateMeshFile(entries[0].mesh, "s", *set, annotate, dir);
  EXPECT_EQ(r.labels.extra["prediction"]["symmetries"].get<int>(), 8);
  ASSERT_EQ(r.predictions.size(), 2u);
  // The averaged field differs from the plain one (the untrained model is not symmetric).
  const ModelPrediction plain = predictWithModel(*set->forCategory("stove")[0], stoveFeatures,
                                                 SurfaceScene(importMesh(entries[0].mesh)),
                                                 UpAxis::Y, InstanceMode::Auto);
  ASSERT_EQ(plain.field.distances.size(), r.predictions[0].field.distances.size());
  EXPECT_NE(plain.field.distances, r.predictions[0].field.distances);
  const Mesh mesh = importMesh(entries[0].mesh);
  const SurfaceScene scene(mesh);
  for (const auto& a : r.labels.affordances)
    EXPECT_LT(scene.closestPoint(fileToZUp(a.position, UpAxis::Y)).distance,
              1e-4f * mesh.bounds().diagonal().norm());
}

TEST_F(AnnotateTest, SingleAndCountModesGiveThatManyPoints) {
  annotate.category = "stove";
  annotate.mode = InstanceMode::Single;
  auto r = annotateMeshFile(entries[0].mesh, "s", *set, annotate, dir);
  EXPECT_EQ(r.labels.affordances.size(), 2u);  // one per model
  EXPECT_FALSE(r.categoryRetrieved);
  annotate.counts["heatsource"] = 3;
  r = annotateMeshFile(entries[0].mesh, "s", *set, annotate, dir);
  EXPECT_EQ(r.labels.ofType("heatsource").size(), 3u);
  EXPECT_EQ(r.labels.ofType("togglebutton").size(), 1u);
}

TEST_F(AnnotateTest, UnknownCategoryAndMismatchedFeaturesAreClearErrors) {
  annotate.category = "fridge";
  try {
    annotateMeshFile(entries[0].mesh, "s", *set, annotate, dir);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("fridge"));
  }
  annotate.category = "stove";
  annotate.features.views = 8;  // a different feature configuration than the models were made for
  EXPECT_THROW(annotateMeshFile(entries[0].mesh, "s", *set, annotate, dir), ModelError);
}

TEST_F(AnnotateTest, TheSecondPassFollowsEachCardUnlessTheCallerSays) {
  auto model = test::untrainedModelFor("sink.fluidsource", sinkFeatures);
  model.card().extraction.coarseToFine = true;
  std::vector<model::AffordanceModel> models;
  models.push_back(std::move(model));
  const ModelSet cardSaysYes(std::move(models));
  annotate.category = "sink";
  annotate.mode = InstanceMode::Single;
  const auto pointOf = [&](std::optional<bool> secondPass) {
    annotate.coarseToFine = secondPass;
    const AnnotationResult r = annotateMeshFile(entries[1].mesh, "s", cardSaysYes, annotate, dir);
    EXPECT_EQ(r.labels.affordances.size(), 1u);
    return r.labels.affordances.at(0).position;
  };
  const Eigen::Vector3f byCard = pointOf(std::nullopt), on = pointOf(true), off = pointOf(false);
  EXPECT_EQ(byCard, on);
  EXPECT_NE(byCard, off);  // the second pass moved the point
  // A card without the switch runs one pass unless asked.
  annotate.coarseToFine.reset();
  const AnnotationResult plain = annotateMeshFile(entries[1].mesh, "s", *set, annotate, dir);
  annotate.coarseToFine = false;
  EXPECT_EQ(plain.labels.affordances.at(0).position,
            annotateMeshFile(entries[1].mesh, "s", *set, annotate, dir)
                .labels.affordances.at(0)
                .position);
}

TEST(ModelSetTest, CosineSimilarity) {
  EXPECT_NEAR(cosineSimilarity({1, 0}, {0, 1}), 0.0, 1e-12);
  EXPECT_NEAR(cosineSimilarity({1, 1}, {2, 2}), 1.0, 1e-12);
  EXPECT_EQ(cosineSimilarity({1}, {1, 2}), 0.0);
}

TEST_F(AnnotateTest, TheEvidenceGateRejectsWhatTheCategorysModelsFindTooLittleOf) {
  // A classifier that files the stove under "stove" (its own descriptor), then the gate.
  std::vector<CategorySample> samples;
  for (int i = 0; i < 3; ++i) {
    samples.push_back(
        test::categorySample("stove" + std::to_string(i), "stove", "", stoveFeatures.descriptor));
    samples.push_back(
        test::categorySample("sink" + std::to_string(i), "sink", "", sinkFeatures.descriptor));
    std::vector<float> other = stoveFeatures.descriptor;
    for (float& v : other) v = -v + 0.1f * static_cast<float>(i);
    samples.push_back(test::categorySample("none" + std::to_string(i), "none", "", other));
  }
  auto classifier = CategoryClassifier::train(samples, {});
  classifier.featureBackend = stoveFeatures.backend;
  set->setCategoryClassifier(classifier, "category.json");
  auto run = [&] { return annotateMeshFile(entries[0].mesh, "stove0", *set, annotate, dir / "o"); };
  const AnnotationResult ungated = run();
  ASSERT_EQ(ungated.category, "stove");
  const double evidence = affordanceEvidence(ungated.predictions);
  ASSERT_GT(evidence, 0.0);
  ASSERT_LT(evidence, 1.0);  // room for a threshold above it

  classifier.evidence.thresholds["stove"] = evidence;  // reached exactly: kept
  set->setCategoryClassifier(classifier, "category.json");
  const AnnotationResult kept = run();
  EXPECT_EQ(kept.category, "stove");
  EXPECT_FALSE(kept.labels.affordances.empty());
  EXPECT_DOUBLE_EQ(kept.labels.extra.at("prediction").at("affordance_evidence").get<double>(),
                   evidence);

  classifier.evidence.thresholds["stove"] = (evidence + 1.0) / 2;
  set->setCategoryClassifier(classifier, "category.json");
  const AnnotationResult rejected = run();
  EXPECT_TRUE(rejected.rejected);
  EXPECT_EQ(rejected.category, "none");
  EXPECT_EQ(rejected.labels.object.category, "none");
  EXPECT_EQ(rejected.closestCategory, "stove");
  EXPECT_TRUE(rejected.predictions.empty());
  // No hard gate: the stove's points stay, flagged as suggestions of "stove".
  ASSERT_EQ(rejected.labels.affordances.size(), kept.labels.affordances.size());
  for (const auto& a : rejected.labels.affordances) EXPECT_TRUE(isSuggestion(a));
  EXPECT_EQ(suggestedCategory(rejected.labels), "stove");
  const auto& prediction = rejected.labels.extra.at("prediction");
  EXPECT_EQ(prediction.at("rejected_by"), "evidence");
  EXPECT_EQ(prediction.at("closest_category"), "stove");
  annotate.suggestions = false;  // as before: no points
  EXPECT_TRUE(run().labels.affordances.empty());
  annotate.suggestions = true;

  // A classifier sure of its answer (at or above the gate's ceiling) is not second-guessed either;
  // below it, the models are asked again.
  classifier.evidence.sureProbability = ungated.categorySimilarity;
  set->setCategoryClassifier(classifier, "category.json");
  EXPECT_EQ(run().category, "stove");
  classifier.evidence.sureProbability = std::nextafter(ungated.categorySimilarity, 2.0);
  set->setCategoryClassifier(classifier, "category.json");
  EXPECT_TRUE(run().rejectedByEvidence);
  classifier.evidence.sureProbability.reset();

  // A category the caller names is not second-guessed.
  annotate.category = "stove";
  const AnnotationResult named = run();
  EXPECT_FALSE(named.rejected);
  EXPECT_FALSE(named.labels.affordances.empty());
}

TEST_F(AnnotateTest, ReportsStagesInOrderAndStopsWhenCancelled) {
  std::vector<std::pair<float, std::string>> stages;
  annotate.onProgress = [&](float fraction, const std::string& stage) {
    stages.emplace_back(fraction, stage);
  };
  annotate.category = "stove";
  annotateMeshFile(entries[0].mesh, "stove0", *set, annotate, dir / "out" / "stove0");
  std::vector<std::string> names;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    names.push_back(stages[i].second);
    if (i > 0) {
      EXPECT_GT(stages[i].first, stages[i - 1].first);
    }
  }
  EXPECT_EQ(names, (std::vector<std::string>{"import", "features", "stove.heatsource",
                                             "stove.togglebutton", "done"}));
  EXPECT_FLOAT_EQ(stages.back().first, 1.0f);

  // Cancelled before the first model: no result, no labels written by this call.
  std::atomic<bool> cancel{false};
  annotate.cancel = &cancel;
  annotate.onProgress = [&](float, const std::string& stage) {
    if (stage == "features") cancel = true;
  };
  EXPECT_THROW(
      annotateMeshFile(entries[0].mesh, "stove0", *set, annotate, dir / "out" / "cancelled"),
      Cancelled);
  EXPECT_FALSE(fs::exists(dir / "out" / "cancelled" / "labels.json"));
}

}  // namespace
}  // namespace sagrid

namespace sagrid {
namespace {

TEST(AnnotationFingerprintTest, EveryPassSwitchChangesTheOptionsHash) {
  // A batch re-annotates an object whose labels were written with other options: switching any
  // pass must change the hash it compares.
  const AnnotateOptions defaults;
  std::vector<AnnotateOptions> switched(6, defaults);
  switched[0].learnedDecision = false;
  switched[1].coarseToFine = false;
  switched[2].coarseToFine = true;
  switched[3].symmetries = 1;
  switched[4].suggestions = false;
  switched[5].readFileName = false;
  std::set<std::string> hashes{annotateOptionsHash(defaults)};
  for (const auto& options : switched) hashes.insert(annotateOptionsHash(options));
  EXPECT_EQ(hashes.size(), 7u);
  EXPECT_EQ(annotateOptionsHash(defaults), annotateOptionsHash(AnnotateOptions{}));
}

TEST(AnnotationFingerprintTest, TheUnitsMemoryIsPartOfTheModelsFingerprint) {
  // A batch annotated before the folder remembered sizes guessed units without it: not up to date.
  const auto dir = test::freshTempDir();
  const ModelSet models(std::vector<model::AffordanceModel>{});
  EXPECT_FALSE(modelShas(models, dir).contains(kSizeMemoryFile));
  writeSizeMemory(SizeMemory({}, "hash", 4.0), dir);
  const auto first = modelShas(models, dir);
  ASSERT_TRUE(first.contains(kSizeMemoryFile));
  writeSizeMemory(SizeMemory({}, "hash", 5.0), dir);
  EXPECT_NE(modelShas(models, dir).at(kSizeMemoryFile), first.at(kSizeMemoryFile));
}

TEST(AnnotationFingerprintTest, WhatAProvenanceRecordDeclaresIsPartOfTheFingerprint) {
  // Labels predicted before a provenance.json declared the units and up axis (or by a build that
  // did not read them) are not up to date; labels of an object with no record still are.
  const std::filesystem::path dir = test::freshTempDir();
  AnnotationFingerprint before{"sha", nlohmann::json::object(), "hash",
                               declaredByProvenance(dir / "mesh.obj")};
  EXPECT_TRUE(before.declared.is_null());
  ObjectLabels labels;
  recordFingerprint(labels, before);
  EXPECT_FALSE(labels.extra.at("prediction").contains("declared"));
  EXPECT_TRUE(matchesFingerprint(labels, before));

  test::writeFile(dir / "provenance.json", R"({"up": "y", "meters_per_unit": 0.01})");
  AnnotationFingerprint after = before;
  after.declared = declaredByProvenance(dir / "mesh.obj");
  EXPECT_EQ(after.declared, nlohmann::json({{"up", "y"}, {"meters_per_unit", 0.01}}));
  EXPECT_FALSE(matchesFingerprint(labels, after));
  recordFingerprint(labels, after);
  EXPECT_TRUE(matchesFingerprint(labels, after));
}

}  // namespace
}  // namespace sagrid
