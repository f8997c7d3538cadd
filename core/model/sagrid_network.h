// The SAGrid CNN in libtorch (internal to core/model: includes torch, so only core/model .cpp
// files and the model tests include it). Table I layers (conv + batch norm + ReLU), then a
// 1x1x1 head with Softplus giving D(v) = log(1 + distance) per voxel. One set of weights runs in
// either execution mode: sparse (submanifold convolution over occupied voxels, batch norm over the
// occupied voxels of the batch) or dense (Conv3d over the full grid, as in the paper).
//
// Input per voxel: features + occupancy mask + the object descriptor broadcast. The descriptor is
// constant over an object, so its share of the first convolution is folded: per tap t,
// b_t = W_t[:, descriptor] * d, added per voxel over the taps whose neighbour exists (sparse) or
// lies inside the grid (dense, zero padding) — the naive concatenated input gives the same result
// (tested), at a fraction of the cost when the descriptor is long (paper: 1024-d).
#pragma once

#include <torch/torch.h>

#include <map>
#include <utility>
#include <vector>

#include "core/grid/voxel_grid.h"
#include "core/model/architecture.h"

namespace sagrid::model {

struct NetworkShape {
  Architecture architecture;
  int featureChannels = 0;  // per-voxel features, without the occupancy mask
  int descriptorSize = 0;
  int resolution = kDefaultGridResolution;

  int inputChannels() const { return featureChannels + 1 + descriptorSize; }
};

// One object as the network sees it (plain data; augmentation happens before this).
struct NetworkObject {
  std::vector<VoxelIndex> voxels;  // occupied, unique, inside the grid
  std::vector<float> features;     // voxels.size() * featureChannels
  std::vector<float> descriptor;   // descriptorSize
};

// Several objects concatenated along the voxel axis, with what each mode needs.
struct NetworkBatch {
  torch::Tensor features;     // (N, C + 1): features and the mask (1 at every occupied voxel)
  torch::Tensor descriptors;  // (B, D)
  std::vector<std::int64_t> offsets;  // B + 1 prefix sums of voxel counts
  torch::Tensor denseIndex;           // (N) int64: b * R^3 + linear voxel index (dense mode)
  // (kernel, dilation) -> (N, taps) int64 rows into the batch, N = missing (the zero row).
  std::map<std::pair<int, int>, torch::Tensor> neighbors;
  int batchSize() const { return static_cast<int>(offsets.size()) - 1; }
  std::int64_t voxelCount() const { return offsets.back(); }
};

NetworkBatch makeNetworkBatch(const std::vector<const NetworkObject*>& objects,
                              const NetworkShape& shape, ExecutionMode mode,
                              const torch::Device& device);

class SAGridNetImpl : public torch::nn::Module {
 public:
  explicit SAGridNetImpl(const NetworkShape& shape);

  // D(v) = log(1 + distance) per occupied voxel of the batch, (N). With foldDescriptor = false
  // the descriptor is concatenated to every voxel's input instead (the naive reference).
  torch::Tensor forward(const NetworkBatch& batch, ExecutionMode mode, bool foldDescriptor = true);

  const NetworkShape& shape() const { return m_shape; }

  // The last convolution's weights, its batch norm's scale and shift, and the output head.
  std::vector<torch::Tensor> lastLayerParameters() const;
  // Frozen, batch norm uses the running statistics in training mode too and leaves them as they
  // are (fine-tuning the last layer on a few objects).
  void setFrozenStatistics(bool frozen) { m_frozenStatistics = frozen; }

 private:
  torch::Tensor forwardSparse(const NetworkBatch& batch, bool fold);
  torch::Tensor forwardDense(const NetworkBatch& batch, bool fold);
  torch::Tensor batchNormRelu(const torch::Tensor& x, std::size_t layer);

  NetworkShape m_shape;
  std::vector<torch::Tensor> m_convWeights;  // (Cout, Cin, k, k, k), no bias (batch norm follows)
  std::vector<torch::Tensor> m_bnWeights, m_bnBiases, m_bnMeans, m_bnVars;
  torch::Tensor m_headWeight;  // (1, C_last)
  torch::Tensor m_headBias;    // (1)
  bool m_frozenStatistics = false;
};
TORCH_MODULE(SAGridNet);

// One submanifold sparse convolution: y[v] = sum_t x[rows(v, t)] W_t, rows = N for an absent
// neighbour (a zero row). x (N, Cin), weight (Cout, Cin, k, k, k), rows (N, k^3) -> (N, Cout).
// The backward pass is itself a gather + GEMM (the transposed convolution uses the mirrored
// taps, since the neighbour relation is symmetric) instead of index_select's scatter-add, which
// is serial and slow on the CPU; `reference` uses plain autograd (for the gradient test).
torch::Tensor sparseConvolution(const torch::Tensor& x, const torch::Tensor& weight,
                                const torch::Tensor& rows, bool reference = false);

// Multiply-accumulate operations of one forward pass of one object, counted analytically as this
// implementation executes them: sparse mode multiplies all taps of the `occupiedVoxels` rows
// (absent neighbours are zero rows), dense mode every voxel of the R^3 grid.
double forwardMacs(const NetworkShape& shape, ExecutionMode mode, std::int64_t occupiedVoxels,
                   bool foldDescriptor = true);

}  // namespace sagrid::model
