// Issue 14: model cards are validated against their weights, and every defect names the card.
// Before, an empty type wrote points of type "", `mode: dense` on sparse-trained weights,
// `nms_radius: 0` or a duplicated card silently changed the points, and seven defects gave a
// message without the card's name.
#include "core/model/model_card.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/io/json_file.h"
#include "core/model/affordance_model.h"
#include "support/test_paths.h"
#include "support/untrained_models.h"

namespace sagrid::model {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// A saved card and its weights in a fresh folder; returns the card's path.
fs::path savedCard(const std::string& folder = "") {
  const fs::path dir = test::freshTempDir(folder);
  AffordanceModel model = test::untrainedModelWithDescriptor("stove.heatsource", {0.1f, 0.2f}, {});
  model.card().training = {{"command", "sagrid train --model stove.heatsource --mode sparse"}};
  model.save(dir / "stove.heatsource.json");
  return dir / "stove.heatsource.json";
}

void edit(const fs::path& card, const std::function<void(json&)>& change) {
  json j = readJsonFile(card);
  change(j);
  writeFileAtomic(card, j.dump(2));
}

// The message loading `card` fails with; it must start with the card's path.
std::string loadError(const fs::path& card) {
  try {
    AffordanceModel::load(card);
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), StartsWith(card.string() + ": "));
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    return e.what();
  }
  ADD_FAILURE() << card << " loaded";
  return "";
}

TEST(ModelCardValidation, ACleanCardLoads) {
  const fs::path card = savedCard();
  EXPECT_EQ(AffordanceModel::load(card).card().name, "stove.heatsource");
  EXPECT_EQ(readModelCard(card).file, card);
}

TEST(ModelCardValidation, EmptyTypeIsRefused) {
  const fs::path card = savedCard();
  edit(card, [](json& j) {
    j["type"] = "";
    j["name"] = "stove.";
  });
  EXPECT_THAT(loadError(card), HasSubstr("field \"name\" is invalid"));
  edit(card, [](json& j) { j["name"] = "stove.heatsource"; });
  EXPECT_THAT(loadError(card), HasSubstr("field \"name\" is \"stove.heatsource\" but category "
                                         "and type say \"stove.\""));
}

TEST(ModelCardValidation, ModeMustBeTheOneTheWeightsWereTrainedIn) {
  const fs::path card = savedCard();
  edit(card, [](json& j) { j["mode"] = "dense"; });
  EXPECT_THAT(loadError(card), HasSubstr("field \"mode\" is \"dense\" but the weights were "
                                         "trained in \"sparse\" mode"));
  edit(card, [](json& j) { j["training"] = {{"mode", "sparse"}}; });
  EXPECT_THAT(loadError(card), HasSubstr("trained in \"sparse\""));
  edit(card, [](json& j) { j["mode"] = "fast"; });
  EXPECT_THAT(loadError(card), HasSubstr("field \"mode\" is \"fast\"; expected"));
}

TEST(ModelCardValidation, PointExtractionSettingsMustBePositive) {
  const fs::path card = savedCard();
  edit(card, [](json& j) { j["point_extraction"]["nms_radius"] = 0; });
  EXPECT_THAT(loadError(card), HasSubstr("field \"point_extraction.nms_radius\" is 0.000000"));
  edit(card, [](json& j) { j["point_extraction"]["nms_radius"] = 0.1; j["point_extraction"]["max_distance"] = -1; });
  EXPECT_THAT(loadError(card), HasSubstr("point_extraction.max_distance"));
  edit(card, [](json& j) { j["point_extraction"]["max_distance"] = "far"; });
  EXPECT_THAT(loadError(card), HasSubstr("wrong field type"));
  edit(card, [](json& j) {
    j["point_extraction"]["max_distance"] = 0.04;
    j["point_extraction"]["min_persistence"] = -0.01;
  });
  EXPECT_THAT(loadError(card), HasSubstr("point_extraction.min_persistence"));
}

TEST(ModelCardValidation, CardsWithoutTheNewerCountSettingsReadAsBefore) {
  // Cards written before the relative threshold and the basin depth: absolute, no depth test.
  const fs::path card = savedCard();
  edit(card, [](json& j) {
    j["point_extraction"].erase("max_distance_above_best");
    j["point_extraction"].erase("min_persistence");
  });
  const auto extraction = AffordanceModel::load(card).card().extraction;
  EXPECT_FALSE(extraction.maxDistanceAboveBest);
  EXPECT_EQ(extraction.minPersistence, 0.0f);
}

TEST(ModelCardValidation, ThePerModelSwitchesAreReadAndOlderCardsRunWithoutThem) {
  // The second pass and the crease patches' candidates: off unless the card says so.
  const std::pair<const char*, bool ExtractionSettings::*> switches[] = {
      {"coarse_to_fine", &ExtractionSettings::coarseToFine},
      {"crease_patches", &ExtractionSettings::creasePatches}};
  for (const auto& [name, member] : switches) {
    SCOPED_TRACE(name);
    const fs::path card = savedCard();
    EXPECT_FALSE(AffordanceModel::load(card).card().extraction.*member);  // written as false
    edit(card, [name = name](json& j) { j["point_extraction"][name] = true; });
    const ModelCard read = AffordanceModel::load(card).card();
    EXPECT_TRUE(read.extraction.*member);
    EXPECT_EQ(toJson(read)["point_extraction"][name], true);  // kept on rewrite
    edit(card, [name = name](json& j) { j["point_extraction"].erase(name); });
    EXPECT_FALSE(AffordanceModel::load(card).card().extraction.*member);
    edit(card, [name = name](json& j) { j["point_extraction"][name] = "yes"; });
    EXPECT_THAT(loadError(card), HasSubstr("wrong field type"));
  }
}

TEST(ModelCardValidation, DuplicatedCardInOneFolderIsRefused) {
  const fs::path card = savedCard();
  fs::copy_file(card, card.parent_path() / "stove.heatsource copy.json");
  try {
    listModelCards(card.parent_path());
    FAIL() << "duplicate accepted";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("stove.heatsource.json: model card for stove.heatsource "
                                    "duplicates stove.heatsource copy.json in the same folder"));
  }
}

// The seven defects whose message did not name the card.
TEST(ModelCardValidation, EveryDefectNamesTheCard) {
  const std::pair<const char*, std::function<void(const fs::path&)>> defects[] = {
      {"architecture", [](const fs::path& c) { edit(c, [](json& j) { j["architecture"] = "[3,1]"; }); }},
      {"features.channels", [](const fs::path& c) { edit(c, [](json& j) { j["features"]["channels"] = 0; }); }},
      {"grid_resolution", [](const fs::path& c) { edit(c, [](json& j) { j["grid_resolution"] = -64; }); }},
      {"weights.sha256", [](const fs::path& c) { edit(c, [](json& j) { j["weights"]["sha256"] = "xyz"; }); }},
      {"file not found", [](const fs::path& c) { fs::remove(c.parent_path() / "stove.heatsource.pt"); }},
      {"sha256 differs",
       [](const fs::path& c) { writeFileAtomic(c.parent_path() / "stove.heatsource.pt", "junk"); }},
      {"have shape", [](const fs::path& c) {
         edit(c, [](json& j) {
           j["architecture"] = "[3,1,8]";
           j["weights"]["sha256"] = "";
         });
       }},
      {"descriptor_mean", [](const fs::path& c) {
         edit(c, [](json& j) { j["retrieval"]["descriptor_mean"] = {1, 2, 3}; });
       }},
  };
  for (const auto& [expected, damage] : defects) {
    const fs::path card = savedCard();
    damage(card);
    EXPECT_THAT(loadError(card), HasSubstr(expected));
  }
}

TEST(ModelCardValidation, FeatureMismatchNamesTheCard) {
  const fs::path card = savedCard();
  const AffordanceModel model = AffordanceModel::load(card);
  FeatureGrid grid;
  grid.backend = "other";
  try {
    model.predictDistances(grid);
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_THAT(e.what(), StartsWith(card.string() + ": model stove.heatsource"));
  }
}

}  // namespace
}  // namespace sagrid::model
