// Torch side of AffordanceModel, shared by the model and the trainer (core/model only).
#pragma once

#include <torch/torch.h>

#include "core/features/feature_grid.h"
#include "core/model/affordance_model.h"
#include "core/model/sagrid_network.h"

namespace sagrid::model {

struct AffordanceModelImpl {
  ModelCard card;
  NetworkShape shape;
  ExecutionMode mode = ExecutionMode::Sparse;
  torch::Device device = torch::kCPU;
  SAGridNet net{nullptr};
  // The card's weights.ensemble, loaded in its order (predictDistances averages over them and net
  // while the card still names them).
  std::vector<SAGridNet> members;
};

NetworkShape networkShapeOf(const ModelCard& card);
NetworkObject networkObjectOf(const FeatureGrid& features);

// Named parameters and buffers of the network, serialized / restored as a torch archive.
std::string serializeWeights(SAGridNet& net);
void deserializeWeights(SAGridNet& net, const std::string& bytes, const std::string& nameForErrors);

}  // namespace sagrid::model
