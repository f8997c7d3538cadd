#include "core/model/model_card.h"

#include <algorithm>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/features/feature_grid.h"

namespace sagrid::model {
namespace fs = std::filesystem;
using nlohmann::json;

std::pair<std::string, std::string> splitModelName(const std::string& name) {
  const auto dot = name.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == name.size() ||
      name.find('.', dot + 1) != std::string::npos)
    throw InvalidArgument("model name \"" + name +
                          "\": expected <category>.<type>, e.g. stove.heatsource");
  return {name.substr(0, dot), name.substr(dot + 1)};
}

void ModelCard::checkFeatures(const FeatureGrid& f) const {
  auto mismatch = [&](const std::string& what, const std::string& model, const std::string& got) {
    throw ModelError("model " + name + " was trained with " + what + " " + model +
                     " but the features have " + got +
                     "; extract features with the model's backend settings or retrain");
  };
  if (f.backend != featureBackend) mismatch("feature backend", featureBackend, f.backend);
  if (!featureConfigHash.empty() && f.configHash != featureConfigHash)
    mismatch("feature config", featureConfigHash, f.configHash);
  if (f.channels != featureChannels)
    mismatch("channel count", std::to_string(featureChannels), std::to_string(f.channels));
  if (static_cast<int>(f.descriptor.size()) != descriptorSize)
    mismatch("descriptor size", std::to_string(descriptorSize),
             std::to_string(f.descriptor.size()));
  if (f.resolution != gridResolution)
    mismatch("grid size", std::to_string(gridResolution) + "^3",
             std::to_string(f.resolution) + "^3");
}

std::string ModelCard::sourceTag() const {
  return name + "@" + weightsSha256.substr(0, std::min<std::size_t>(8, weightsSha256.size()));
}

json toJson(const ModelCard& c) {
  json j = c.extra;
  j["schema"] = kModelCardSchema;
  j["name"] = c.name;
  j["category"] = c.category;
  j["type"] = c.type;
  j["architecture"] = c.architecture;
  j["mode"] = c.mode;
  j["features"] = {{"backend", c.featureBackend},
                   {"config_hash", c.featureConfigHash},
                   {"channels", c.featureChannels},
                   {"descriptor_size", c.descriptorSize}};
  j["grid_resolution"] = c.gridResolution;
  j["weights"] = {{"file", c.weightsFile}, {"sha256", c.weightsSha256}};
  j["point_extraction"] = {{"max_distance", c.extraction.maxDistance},
                           {"nms_radius", c.extraction.nmsRadius},
                           {"confidence_scale", c.extraction.confidenceScale},
                           {"refine_voxels", c.extraction.refineVoxels}};
  j["retrieval"] = {{"descriptor_mean", c.descriptorMean}, {"descriptor_std", c.descriptorStd}};
  j["embedding_search"] = {{"affordance_feature_mean", c.affordanceFeatureMean}};
  j["training"] = c.training;
  j["metrics"] = c.metrics;
  return j;
}

ModelCard modelCardFromJson(const json& j, const fs::path& path) {
  auto field = [&](const json& parent, const char* key, const std::string& where) -> const json& {
    if (!parent.is_object() || !parent.contains(key))
      throw FileError(path, "model card: missing field \"" + where + key + "\"");
    return parent.at(key);
  };
  try {
    if (!j.is_object()) throw FileError(path, "model card: not a JSON object");
    const std::string schema = field(j, "schema", "").get<std::string>();
    if (schema != kModelCardSchema)
      throw FileError(path, "model card: unknown schema \"" + schema + "\" (expected " +
                                kModelCardSchema + ")");
    ModelCard c;
    c.name = field(j, "name", "").get<std::string>();
    c.category = field(j, "category", "").get<std::string>();
    c.type = field(j, "type", "").get<std::string>();
    c.architecture = field(j, "architecture", "").get<std::string>();
    c.mode = field(j, "mode", "").get<std::string>();
    const json& f = field(j, "features", "");
    c.featureBackend = field(f, "backend", "features.").get<std::string>();
    c.featureConfigHash = field(f, "config_hash", "features.").get<std::string>();
    c.featureChannels = field(f, "channels", "features.").get<int>();
    c.descriptorSize = field(f, "descriptor_size", "features.").get<int>();
    c.gridResolution = field(j, "grid_resolution", "").get<int>();
    const json& w = field(j, "weights", "");
    c.weightsFile = field(w, "file", "weights.").get<std::string>();
    c.weightsSha256 = field(w, "sha256", "weights.").get<std::string>();
    if (j.contains("point_extraction")) {
      const json& p = j.at("point_extraction");
      c.extraction.maxDistance = p.value("max_distance", c.extraction.maxDistance);
      c.extraction.nmsRadius = p.value("nms_radius", c.extraction.nmsRadius);
      c.extraction.confidenceScale = p.value("confidence_scale", c.extraction.confidenceScale);
      c.extraction.refineVoxels = p.value("refine_voxels", c.extraction.refineVoxels);
    }
    if (j.contains("retrieval")) {
      c.descriptorMean = j.at("retrieval").value("descriptor_mean", std::vector<float>{});
      c.descriptorStd = j.at("retrieval").value("descriptor_std", std::vector<float>{});
    }
    if (j.contains("embedding_search"))
      c.affordanceFeatureMean =
          j.at("embedding_search").value("affordance_feature_mean", std::vector<float>{});
    c.training = j.value("training", json::object());
    c.metrics = j.value("metrics", json::object());
    c.extra = j;
    for (const char* known : {"schema", "name", "category", "type", "architecture", "mode",
                              "features", "grid_resolution", "weights", "point_extraction",
                              "retrieval", "embedding_search", "training", "metrics"})
      c.extra.erase(known);
    if (c.weightsFile.empty() || c.weightsFile.find('/') != std::string::npos)
      throw FileError(path, "model card: weights.file must be a file name beside the card");
    return c;
  } catch (const json::exception& e) {
    throw FileError(path, std::string("model card: wrong field type (") + e.what() + ")");
  }
}

ModelCard readModelCard(const fs::path& cardFile) {
  const std::string bytes = readFileBytes(cardFile);
  json j;
  try {
    j = json::parse(bytes);
  } catch (const json::exception& e) {
    throw FileError(cardFile, std::string("model card is not valid JSON: ") + e.what());
  }
  return modelCardFromJson(j, cardFile);
}

void writeModelCard(const fs::path& cardFile, const ModelCard& card) {
  writeFileAtomic(cardFile, toJson(card).dump(2) + "\n");
}

std::vector<fs::path> listModelCards(const fs::path& directory) {
  if (!fs::is_directory(directory)) throw FileError(directory, "model directory not found");
  std::vector<fs::path> cards;
  for (const auto& entry : fs::directory_iterator(directory))
    // Cards are <category>.<type>.json; other JSON beside them (category.json, the category
    // classifier; confidence.json) is not a card.
    if (entry.is_regular_file() && entry.path().extension() == ".json" &&
        entry.path().stem().string().find('.') != std::string::npos)
      cards.push_back(entry.path());
  std::sort(cards.begin(), cards.end());
  if (cards.empty())
    throw ModelError(directory.string() +
                     ": no model cards (*.json); train models with "
                     "`sagrid train` or use --models");
  return cards;
}

}  // namespace sagrid::model
