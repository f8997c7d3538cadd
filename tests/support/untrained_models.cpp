#include "support/untrained_models.h"

#include <tuple>

namespace sagrid::test {

model::AffordanceModel untrainedModelFor(const std::string& name, const FeatureGrid& grid,
                                         unsigned seed) {
  model::ModelCard card;
  card.name = name;
  std::tie(card.category, card.type) = model::splitModelName(name);
  card.architecture = "[3,1,4],[3,2,4,2]";
  card.featureBackend = grid.backend;
  card.featureConfigHash = grid.configHash;
  card.featureChannels = grid.channels;
  card.descriptorSize = static_cast<int>(grid.descriptor.size());
  card.gridResolution = grid.resolution;
  card.descriptorMean = grid.descriptor;
  card.affordanceFeatureMean.assign(grid.channels, 0.5f);
  return model::AffordanceModel(card, seed);
}

model::AffordanceModel untrainedModelWithDescriptor(const std::string& name,
                                                    std::vector<float> mean,
                                                    std::vector<float> spread) {
  model::ModelCard card;
  card.name = name;
  std::tie(card.category, card.type) = model::splitModelName(name);
  card.architecture = "[3,1,4]";
  card.featureBackend = "embedded";
  card.featureChannels = 2;
  card.descriptorSize = static_cast<int>(mean.size());
  card.descriptorMean = std::move(mean);
  card.descriptorStd = std::move(spread);
  return model::AffordanceModel(card, 1);
}

}  // namespace sagrid::test
