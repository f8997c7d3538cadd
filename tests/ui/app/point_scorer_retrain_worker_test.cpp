// The Train panel's "Retrain point decision" (issue 40, item 1): the points curated in the GUI's
// training set and generated objects retrain the learned point decision of the loaded models,
// guarded on held-out curated objects; the loaded decision is never overwritten, the verdict per
// model shows in the panel and goes to scorer_guard.json, and an adopted decision predicts the
// queue's unreviewed objects again.
#include <gtest/gtest.h>

#include <map>

#include <nlohmann/json.hpp>

#include "core/annotate/model_set.h"
#include "core/annotate/point_scorer.h"
#include "core/common/atomic_file.h"
#include "core/dataset/dataset.h"
#include "core/generate/dataset_generator.h"
#include "core/labels/labels.h"
#include "core/model/model_card.h"
#include "support/test_paths.h"
#include "ui/app/training_worker.h"
#include "training_worker_support.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

const fs::path kShipped = fs::path(SAGRID_SOURCE_DIR) / "resources" / "models";

TrainingStatus retrainDecision(const fs::path& dir, const fs::path& curated,
                               std::vector<QueueEntry> requeue = {}) {
  TrainingRequest request = test::requestIn(dir);
  request.requeue = std::move(requeue);
  request.dataset = curated;
  request.heldOut = dir / "held-out";
  request.generated = dir / "generated";
  request.pointScorer = true;
  return test::runToEnd(std::move(request), 600);
}

// Generated stand-ins for the curator's training set, the generated objects and held-out curated
// objects, and the loaded models (the shipped ones), in `dir`.
void prepare(const fs::path& dir) {
  gen::generateDataset({{"stove", 2, 61}, {"sink", 2, 62}}, gen::MeshFormat::Obj, dir / "generated");
  gen::generateDataset({{"stove", 1, 64}, {"sink", 1, 65}}, gen::MeshFormat::Obj, dir / "curated");
  gen::generateDataset({{"stove", 1, 67}, {"sink", 1, 68}}, gen::MeshFormat::Obj, dir / "held-out");
  // A stove whose curator deleted every point.
  gen::generateDataset({{"stove", 1, 69}}, gen::MeshFormat::Obj, dir / "no-points");
  for (const auto& entry : readDataset(dir / "no-points")) {
    ObjectLabels labels = readLabels(entry.labels);
    labels.affordances.clear();
    writeLabels(entry.labels, labels);
  }
  fs::copy(kShipped, dir / "loaded", fs::copy_options::recursive);
}

// The retrained decision is judged on the held-out objects, each category's mixes of new and
// loaded decisions as a whole: a model's new decision goes into the models folder out exactly
// when it is in its category's best mix, which needs fewer edits than the loaded decisions; the
// others keep the loaded one's (the whole new scorer goes to refused/ where any model refused it),
// with one verdict per model and the figures in scorer_guard.json; it switches off the passes the
// loaded one did; the loaded file is untouched; adopted, the unreviewed object of the queue is
// predicted again, the accepted one not.
TEST(PointScorerRetrainWorker, TheRetrainedDecisionGoesWhereTheHeldOutEditsSay) {
  const fs::path dir = test::freshTempDir();
  prepare(dir);
  const std::string loaded = readFileBytes(dir / "loaded" / kPointScorerFile);
  const auto queue =
      test::reviewQueue(dir, readDataset(dir / "held-out").front().mesh, "stove");
  const std::string accepted = readFileBytes(queue[1].labels);

  const TrainingStatus status = retrainDecision(dir, dir / "curated", queue);
  ASSERT_TRUE(status.error.empty()) << status.error;
  const auto guard = nlohmann::json::parse(readFileBytes(dir / "out" / "scorer_guard.json"));
  bool anyAdopted = false, allAdopted = true;
  std::map<std::string, bool> categoryAdopted;  // any of the category's models adopted
  for (const auto& m : guard.at("models"))
    categoryAdopted[model::splitModelName(m.at("model")).first] |= m.at("adopted").get<bool>();
  for (const auto& m : guard.at("models")) {
    // Judged with the category's other models (each count reads them): a model is adopted only
    // in a mix that needs fewer edits on its category's objects.
    const bool adopted = m.at("adopted").get<bool>();
    if (adopted)
      EXPECT_LT(m.at("category_adopted_edits").get<int>(), m.at("category_current_edits").get<int>())
          << m.dump();
    // A mix with fewer edits was found exactly when one of the category's models was adopted.
    EXPECT_EQ(m.at("category_adopted_edits").get<int>() < m.at("category_current_edits").get<int>(),
              categoryAdopted.at(model::splitModelName(m.at("model")).first))
        << m.dump();
    anyAdopted = anyAdopted || adopted;
    allAdopted = allAdopted && adopted;
  }
  const bool adopted = guard.at("adopted").get<bool>();
  EXPECT_EQ(adopted, anyAdopted) << guard.dump();
  ASSERT_EQ(status.verdicts.size(), guard.at("models").size() + 1);
  EXPECT_NE(status.verdicts.back().find(adopted ? ": adopted" : ": refused"), std::string::npos)
      << status.verdicts.back();
  EXPECT_EQ(fs::exists(dir / "out" / "refused" / kPointScorerFile), !allAdopted);
  // The GUI predicts from the folder out afterwards: a whole models folder either way, each model
  // with the retrained decision where adopted and the loaded one where refused.
  const ModelSet out = ModelSet::load(dir / "out");
  ASSERT_NE(out.pointScorer(), nullptr);
  const PointScorer before = *readPointScorer(dir / "loaded");
  const PointScorer fresh = *readPointScorer(allAdopted ? dir / "out" : dir / "out" / "refused");
  EXPECT_EQ(out.pointScorer()->passesOff, before.passesOff);
  for (const auto& m : guard.at("models")) {
    const std::string model = m.at("model");
    const ModelPointScorer* want =
        (m.at("adopted").get<bool>() ? fresh : before).forModel(model);
    const ModelPointScorer* got = out.pointScorer()->forModel(model);
    ASSERT_EQ(got == nullptr, want == nullptr) << model;
    if (!got) continue;
    PointScorer a, b;
    a.byModel[model] = *got;
    b.byModel[model] = *want;
    EXPECT_EQ(toJson(a).dump(), toJson(b).dump()) << model;
  }
  if (!adopted) EXPECT_EQ(readFileBytes(dir / "out" / kPointScorerFile), loaded);
  EXPECT_EQ(readFileBytes(dir / "loaded" / kPointScorerFile), loaded);
  EXPECT_EQ(readFileBytes(queue[1].labels), accepted);
  EXPECT_EQ(!readLabels(queue[0].labels).affordances.empty(), adopted);
}

// Curated objects with no point of any model give the decision nothing to learn: the panel says
// so and nothing is written.
TEST(PointScorerRetrainWorker, ATrainingSetWithoutPointsIsRefusedWithItsReason) {
  const fs::path dir = test::freshTempDir();
  prepare(dir);
  const TrainingStatus status = retrainDecision(dir, dir / "no-points");
  EXPECT_NE(status.error.find("nothing to learn"), std::string::npos) << status.error;
  EXPECT_FALSE(fs::exists(dir / "out" / kPointScorerFile));
  EXPECT_FALSE(fs::exists(dir / "out" / "refused"));
}

}  // namespace
}  // namespace sagrid::ui
