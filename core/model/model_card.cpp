#include "core/model/model_card.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/features/feature_grid.h"
#include "core/io/json_file.h"
#include "core/model/architecture.h"

namespace sagrid::model {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {
bool isFileNameBeside(const std::string& name) {
  return !name.empty() && name.find('/') == std::string::npos &&
         name.find('\\') == std::string::npos && name != "." && name != "..";
}
bool isSha256Hex(const std::string& text) {
  return text.size() == 64 && std::all_of(text.begin(), text.end(), ::isxdigit);
}
}  // namespace

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
    throw ModelError((file.empty() ? "" : file.string() + ": ") + "model " + name +
                     " was trained with " + what + " " + model +
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

std::optional<NetworkDifference> networkDifference(const ModelCard& a, const ModelCard& b) {
  const NetworkDifference fields[] = {
      {"model", a.name, b.name},
      {"architecture", a.architecture, b.architecture},
      {"mode", a.mode, b.mode},
      {"feature backend", a.featureBackend, b.featureBackend},
      {"feature config", a.featureConfigHash,
       a.featureConfigHash.empty() ? "" : b.featureConfigHash},
      {"feature channels", std::to_string(a.featureChannels), std::to_string(b.featureChannels)},
      {"descriptor size", std::to_string(a.descriptorSize), std::to_string(b.descriptorSize)},
      {"grid", std::to_string(a.gridResolution) + "^3", std::to_string(b.gridResolution) + "^3"}};
  for (const auto& f : fields)
    if (f.a != f.b) return f;
  return std::nullopt;
}

std::string ModelCard::weightsIdentity() const {
  if (ensemble.empty()) return weightsSha256;
  std::string shas = weightsSha256;
  for (const auto& member : ensemble) shas += " " + member.sha256;
  return sha256Hex(shas);
}

std::string ModelCard::sourceTag() const {
  const std::string identity = weightsIdentity();
  return name + "@" + identity.substr(0, std::min<std::size_t>(8, identity.size()));
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
  for (const auto& member : c.ensemble)
    j["weights"]["ensemble"].push_back({{"file", member.file}, {"sha256", member.sha256}});
  j["point_extraction"] = {{"max_distance", c.extraction.maxDistance},
                           {"nms_radius", c.extraction.nmsRadius},
                           {"confidence_scale", c.extraction.confidenceScale},
                           {"refine_voxels", c.extraction.refineVoxels},
                           {"max_distance_above_best", c.extraction.maxDistanceAboveBest},
                           {"min_persistence", c.extraction.minPersistence},
                           {"coarse_to_fine", c.extraction.coarseToFine},
                           {"crease_patches", c.extraction.creasePatches}};
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
    if (w.contains("ensemble")) {
      const json& members = w.at("ensemble");
      if (!members.is_array())
        throw FileError(path, "model card: weights.ensemble must be a list of {file, sha256}");
      for (const json& m : members)
        c.ensemble.push_back({field(m, "file", "weights.ensemble[].").get<std::string>(),
                              field(m, "sha256", "weights.ensemble[].").get<std::string>()});
    }
    if (j.contains("point_extraction")) {
      const json& p = j.at("point_extraction");
      c.extraction.maxDistance = p.value("max_distance", c.extraction.maxDistance);
      c.extraction.nmsRadius = p.value("nms_radius", c.extraction.nmsRadius);
      c.extraction.confidenceScale = p.value("confidence_scale", c.extraction.confidenceScale);
      c.extraction.refineVoxels = p.value("refine_voxels", c.extraction.refineVoxels);
      // Cards written before the relative threshold and the depth test read as without them.
      c.extraction.maxDistanceAboveBest =
          p.value("max_distance_above_best", c.extraction.maxDistanceAboveBest);
      c.extraction.minPersistence = p.value("min_persistence", c.extraction.minPersistence);
      c.extraction.coarseToFine = p.value("coarse_to_fine", c.extraction.coarseToFine);
      c.extraction.creasePatches = p.value("crease_patches", c.extraction.creasePatches);
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
    return c;
  } catch (const json::exception& e) {
    throw FileError(path, std::string("model card: wrong field type (") + e.what() + ")");
  }
}

namespace {

// The execution mode the weights were trained in: training.mode, else the --mode of the recorded
// training command (cards written before training.mode existed); "" when the card does not say.
std::string trainedMode(const json& training) {
  if (auto it = training.find("mode"); it != training.end() && it->is_string())
    return it->get<std::string>();
  const std::string command = training.value("command", std::string());
  const auto at = command.find("--mode ");
  if (at == std::string::npos) return "";
  const auto start = at + 7, end = command.find(' ', start);
  return command.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The checks a card must pass before its numbers steer a network or point extraction; every
// message names the card and the field.
void validateCard(const ModelCard& c, const fs::path& path) {
  auto fail = [&](const std::string& field, const std::string& problem) {
    throw FileError(path, "model card: field \"" + field + "\" " + problem);
  };
  try {
    const auto [category, type] = splitModelName(c.name);
    if (c.category != category || c.type != type)
      fail("name", "is \"" + c.name + "\" but category and type say \"" + c.category + "." +
                       c.type + "\"");
  } catch (const InvalidArgument& e) {
    fail("name", std::string("is invalid: ") + e.what());
  }
  if (c.type.empty()) fail("type", "is empty");
  try {
    Architecture::parse(c.architecture);
  } catch (const InvalidArgument& e) {
    fail("architecture", std::string("is invalid: ") + e.what());
  }
  if (c.mode != "sparse" && c.mode != "dense")
    fail("mode", "is \"" + c.mode + "\"; expected \"sparse\" or \"dense\"");
  const std::string trained = trainedMode(c.training);
  if (!trained.empty() && trained != c.mode)
    fail("mode", "is \"" + c.mode + "\" but the weights were trained in \"" + trained +
                     "\" mode (training); set it back or retrain");
  if (c.featureBackend.empty()) fail("features.backend", "is empty");
  if (c.featureChannels < 1 || c.featureChannels > 4096)
    fail("features.channels", "is " + std::to_string(c.featureChannels) + "; expected 1..4096");
  if (c.descriptorSize < 0 || c.descriptorSize > 65536)
    fail("features.descriptor_size",
         "is " + std::to_string(c.descriptorSize) + "; expected 0..65536");
  if (c.gridResolution < 1 || c.gridResolution > 1024)
    fail("grid_resolution", "is " + std::to_string(c.gridResolution) + "; expected 1..1024");
  if (!isFileNameBeside(c.weightsFile)) fail("weights.file", "must be a file name beside the card");
  if (!c.weightsSha256.empty() && !isSha256Hex(c.weightsSha256))
    fail("weights.sha256", "is not 64 hex digits");
  for (const auto& member : c.ensemble) {
    if (!isFileNameBeside(member.file) || member.file == c.weightsFile)
      fail("weights.ensemble[].file",
           "\"" + member.file + "\" must be another file name beside the card");
    // A member's sha256 is required: nothing else ties the file to the card.
    if (!isSha256Hex(member.sha256))
      fail("weights.ensemble[].sha256", "of " + member.file + " is not 64 hex digits");
  }
  const std::pair<const char*, float> positive[] = {
      {"point_extraction.max_distance", c.extraction.maxDistance},
      {"point_extraction.nms_radius", c.extraction.nmsRadius},
      {"point_extraction.confidence_scale", c.extraction.confidenceScale}};
  for (const auto& [field, value] : positive)
    if (!(std::isfinite(value) && value > 0 && value <= 10))
      fail(field, "is " + std::to_string(value) + "; expected a number in (0, 10]");
  if (!(std::isfinite(c.extraction.refineVoxels) && c.extraction.refineVoxels >= 0 &&
        c.extraction.refineVoxels <= 64))
    fail("point_extraction.refine_voxels", "must be a number in [0, 64]");
  if (!(std::isfinite(c.extraction.minPersistence) && c.extraction.minPersistence >= 0 &&
        c.extraction.minPersistence <= 10))
    fail("point_extraction.min_persistence", "must be a number in [0, 10]");
  auto statistics = [&](const char* field, const std::vector<float>& values, int expected) {
    if (!values.empty() && static_cast<int>(values.size()) != expected)
      fail(field, "has " + std::to_string(values.size()) + " values but the features have " +
                      std::to_string(expected));
    for (float v : values)
      if (!std::isfinite(v)) fail(field, "holds a value that is not finite");
  };
  statistics("retrieval.descriptor_mean", c.descriptorMean, c.descriptorSize);
  statistics("retrieval.descriptor_std", c.descriptorStd, c.descriptorSize);
  statistics("embedding_search.affordance_feature_mean", c.affordanceFeatureMean,
             c.featureChannels);
}

}  // namespace

ModelCard readModelCard(const fs::path& cardFile) {
  ModelCard card = modelCardFromJson(readJsonFile(cardFile), cardFile);
  validateCard(card, cardFile);
  card.file = cardFile;
  return card;
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
  // Two cards for one model would silently replace each other's points.
  std::map<std::string, fs::path> byName;
  for (const auto& card : cards) {
    const std::string name = readModelCard(card).name;
    if (auto [it, fresh] = byName.emplace(name, card); !fresh)
      throw FileError(card, "model card for " + name + " duplicates " +
                                it->second.filename().string() +
                                " in the same folder; keep one card per model");
  }
  if (cards.empty())
    throw ModelError(directory.string() +
                     ": no model cards (*.json); train models with "
                     "`sagrid train` or use --models");
  return cards;
}

std::map<std::string, std::string> cardWeights(const fs::path& directory) {
  std::map<std::string, std::string> out;
  for (const auto& file : listModelCards(directory)) {
    const ModelCard card = readModelCard(file);
    out[card.name] = card.weightsIdentity();
  }
  return out;
}

}  // namespace sagrid::model
