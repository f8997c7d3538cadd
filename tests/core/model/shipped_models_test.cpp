// The default models shipped in resources/models: each card's sha256 matches its weights, each
// loads and predicts a plausible field on a freshly generated object of its category, and the
// shipped point decision learned from the candidates of these very networks.
#include <gtest/gtest.h>

#include "core/annotate/object_confidence.h"
#include "core/annotate/point_scorer.h"
#include "core/common/atomic_file.h"
#include "core/common/sha256.h"
#include "core/dataset/dataset.h"
#include "core/features/feature_pipeline.h"
#include "core/generate/dataset_generator.h"
#include "core/model/affordance_model.h"
#include "core/training/dataset_training.h"
#include "support/test_paths.h"

namespace sagrid::model {
namespace {
namespace fs = std::filesystem;

const fs::path kModels = fs::path(SAGRID_SOURCE_DIR) / "resources" / "models";

TEST(ShippedModels, CardsMatchTheirWeightsAndStayUnder20MB) {
  std::uintmax_t total = 0;
  for (const auto& name : defaultModelNames()) {
    const fs::path cardFile = kModels / (name + ".json");
    ASSERT_TRUE(fs::exists(cardFile)) << cardFile;
    const ModelCard card = readModelCard(cardFile);
    EXPECT_EQ(card.name, name);
    const std::string weights = readFileBytes(kModels / card.weightsFile);
    EXPECT_EQ(sha256Hex(weights), card.weightsSha256) << name;
    EXPECT_EQ(card.featureBackend, "embedded");
    EXPECT_EQ(card.descriptorMean.size(), static_cast<std::size_t>(card.descriptorSize));
    EXPECT_EQ(card.affordanceFeatureMean.size(), static_cast<std::size_t>(card.featureChannels));
    EXPECT_FALSE(card.training.value("command", "").empty());
    total += weights.size() + fs::file_size(cardFile);
    for (const auto& member : card.ensemble) {
      const std::string memberWeights = readFileBytes(kModels / member.file);
      EXPECT_EQ(sha256Hex(memberWeights), member.sha256) << member.file;
      total += memberWeights.size();
    }
  }
  EXPECT_LE(total, 20u * 1024 * 1024);
}

// A network retrained without its decision (make models, a fine-tune) fails here: retrain the
// decision too (`sagrid scorer train`), so that the shipped folder never mixes versions.
TEST(ShippedModels, ThePointDecisionLearnedFromTheShippedNetworks) {
  const auto scorer = sagrid::readPointScorer(kModels);
  ASSERT_TRUE(scorer.has_value());
  ASSERT_FALSE(scorer->byModel.empty());
  for (const auto& [name, decision] : scorer->byModel)
    EXPECT_EQ(decision.networkWeights, readModelCard(kModels / (name + ".json")).weightsIdentity())
        << name;
}

TEST(ShippedModels, TheObjectConfidenceWasFittedOnTheShippedNetworks) {
  const ConfidenceCalibration confidence = readConfidenceCalibration(kModels);
  EXPECT_TRUE(confidence.fitted);
  EXPECT_EQ(confidence.networkWeights, cardWeights(kModels));
}

TEST(ShippedModels, EachLoadsAndPredictsOnAGeneratedObject) {
  const fs::path dir = test::freshTempDir();
  // Seeds outside the bench split, so these objects were never seen in training.
  gen::generateDataset({{"stove", 1, 777}, {"sink", 1, 777}}, gen::MeshFormat::Obj, dir);
  const auto entries = readDataset(dir);
  ASSERT_EQ(entries.size(), 2u);
  for (const auto& name : defaultModelNames()) {
    const AffordanceModel model = AffordanceModel::load(kModels / (name + ".json"));
    const auto& entry = entries[model.card().category == "stove" ? 0 : 1];
    FeatureOptions options;
    options.backend = model.card().featureBackend;
    const FeatureGrid features = extractFeatures(entry.mesh, options);
    const std::vector<float> d = model.predictDistances(features);
    ASSERT_EQ(d.size(), features.voxels.size()) << name;
    const float lo = *std::min_element(d.begin(), d.end()), hi = *std::max_element(d.begin(), d.end());
    EXPECT_GE(lo, 0.0f) << name;
    // A field, not a constant: the nearest voxel is much closer than the farthest.
    EXPECT_GT(hi, 2 * lo + 0.05f) << name << " lo " << lo << " hi " << hi;
  }
}

}  // namespace
}  // namespace sagrid::model
