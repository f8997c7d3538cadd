// The model card: everything needed to use, check and reproduce one SAGrid model
// (DESIGN.md "Model"): architecture and execution mode, the feature backend it was trained on
// (name, config hash, channel counts), grid size, training data and command, metrics, the sha256
// of its weights, the descriptor mean of its category (for retrieval) and the calibrated
// point-extraction settings. Stored as <category>.<type>.json beside <category>.<type>.pt.
// Plain C++ (no torch): annotate, filter and eval read cards without touching the network.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/points/point_extraction.h"

namespace sagrid {
struct FeatureGrid;
}

namespace sagrid::model {

inline constexpr const char* kModelCardSchema = "sagrid.model/1";

// Weights of one network beside the card.
struct WeightsFile {
  std::string file;  // relative to the card
  std::string sha256;
};

struct ModelCard {
  std::string name;      // "<category>.<type>", e.g. "stove.heatsource"
  std::string category;  // "stove"
  std::string type;      // "heatsource"
  std::string architecture;
  std::string mode = "sparse";
  std::string featureBackend;
  std::string featureConfigHash;
  int featureChannels = 0;
  int descriptorSize = 0;
  int gridResolution = 64;
  std::string weightsFile;  // relative to the card
  std::string weightsSha256;
  // weights.ensemble: more networks of the same architecture and features, trained apart (other
  // data, other seed), whose predicted distances are averaged with the main weights' (the mean
  // field of two networks has fewer spurious minima than either; the shipped stove.togglebutton).
  // Empty: the main weights alone.
  std::vector<WeightsFile> ensemble;
  std::vector<float> descriptorMean;         // mean descriptor of the category's training objects
  std::vector<float> descriptorStd;          // their per-dimension spread (empty on old cards)
  std::vector<float> affordanceFeatureMean;  // mean voxel feature at training affordances
  ExtractionSettings extraction;
  nlohmann::json training = nlohmann::json::object();  // data, command, objects, epochs, time...
  nlohmann::json metrics = nlohmann::json::object();
  nlohmann::json extra = nlohmann::json::object();  // unknown fields, kept on rewrite
  std::filesystem::path file;  // where readModelCard read it (for messages); not written

  // Throws ModelError naming what differs when the features were not made the way the model
  // was trained (backend, config hash, channel count, descriptor size, grid size).
  void checkFeatures(const FeatureGrid& features) const;
  // What predicts: the main weights' sha256, or with an ensemble the sha256 of every member's
  // sha256 in order (what annotation fingerprints and the evidence gate record).
  std::string weightsIdentity() const;
  std::string sourceTag() const;  // "stove.heatsource@<first 8 hex of weightsIdentity()>"
};

// What makes the network of one card unusable in place of another's: the first of model name,
// architecture, mode, feature backend, feature config (when `a` records one), feature channels,
// descriptor size and grid in which they differ, with both values; nullopt when none does
// (fine-tuning from an init model, adding an ensemble member).
struct NetworkDifference {
  std::string what, a, b;
};
std::optional<NetworkDifference> networkDifference(const ModelCard& a, const ModelCard& b);

// "stove.heatsource" -> {"stove", "heatsource"}; throws InvalidArgument otherwise.
std::pair<std::string, std::string> splitModelName(const std::string& name);

nlohmann::json toJson(const ModelCard& card);
ModelCard modelCardFromJson(const nlohmann::json& json, const std::filesystem::path& pathForErrors);
// Throws FileError naming the card and the field: not JSON, missing or mistyped fields, a name
// that is not <category>.<type> or disagrees with them, an empty type, an architecture that does
// not parse, a mode other than sparse/dense or other than the one the weights were trained in,
// channel counts, grid size or point-extraction settings out of range, statistics whose size
// disagrees with the channel counts.
ModelCard readModelCard(const std::filesystem::path& cardFile);
void writeModelCard(const std::filesystem::path& cardFile, const ModelCard& card);  // atomic

// Every *.json model card in a directory, sorted by name, each read and validated; throws
// FileError when the directory is missing, a card is invalid or two cards name the same model,
// ModelError when it holds no cards.
std::vector<std::filesystem::path> listModelCards(const std::filesystem::path& directory);

// Model name -> ModelCard::weightsIdentity() of every card in a directory (as listModelCards).
std::map<std::string, std::string> cardWeights(const std::filesystem::path& directory);

}  // namespace sagrid::model
