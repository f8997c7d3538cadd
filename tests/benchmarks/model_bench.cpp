// SAGrid network speed on a stove-sized object (surface of a 60 x 44 x 52 box at 64^3: ~20k
// occupied voxels, 16 feature channels, 64-d descriptor): inference forward pass and a training
// step (forward + backward), sparse mode, for the default architecture and others.
#include <benchmark/benchmark.h>

#include <random>

#include "core/common/thread_count.h"
#include "core/model/affordance_model_impl.h"
#include "core/model/sagrid_network.h"

namespace {
using namespace sagrid::model;

NetworkObject boxSurface() {
  NetworkObject o;
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> value(0, 1);
  for (int i = 2; i < 62; ++i)
    for (int j = 10; j < 54; ++j)
      for (int k = 6; k < 58; ++k)
        if (i == 2 || i == 61 || j == 10 || j == 53 || k == 6 || k == 57)
          o.voxels.push_back({i, j, k});
  for (std::size_t v = 0; v < o.voxels.size() * 16; ++v) o.features.push_back(value(rng));
  for (int d = 0; d < 64; ++d) o.descriptor.push_back(value(rng));
  return o;
}

NetworkShape shapeFor(const std::string& arch) {
  NetworkShape s;
  s.architecture = Architecture::parse(arch);
  s.featureChannels = 16;
  s.descriptorSize = 64;
  return s;
}

const char* const kArchitectures[] = {
    kDefaultArchitecture, "[3,1,16],[3,2,16,2],[3,4,16,4],[3,1,16]", "[3,1,32],[3,1,16]"};

void BM_SparseForward(benchmark::State& state) {
  configureTorchRuntime();
  const auto object = boxSurface();
  const auto shape = shapeFor(kArchitectures[state.range(0)]);
  SAGridNet net(shape);
  net->eval();
  torch::NoGradGuard noGrad;
  for (auto _ : state) {
    const auto batch = makeNetworkBatch({&object}, shape, ExecutionMode::Sparse, torch::kCPU);
    benchmark::DoNotOptimize(net->forward(batch, ExecutionMode::Sparse).sum().item<float>());
  }
  state.SetLabel(
      std::string(kArchitectures[state.range(0)]) + ", " + std::to_string(object.voxels.size()) +
      " voxels, " +
      std::to_string(forwardMacs(shape, ExecutionMode::Sparse, object.voxels.size()) / 1e9) +
      " GMAC");
}
BENCHMARK(BM_SparseForward)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// One 16 -> 16 channel 3^3 layer on the box surface, one thread (as annotate runs each pass):
// 0 = the gathered input times the tap matrix (plain autograd, the reference), 1 = each tap's
// products added per voxel (what the network runs).
void BM_SparseConvolutionLayer(benchmark::State& state) {
  configureTorchRuntime();
  at::set_num_threads(1);
  const auto object = boxSurface();
  const auto shape = shapeFor("[3,1,16]");
  const auto batch = makeNetworkBatch({&object}, shape, ExecutionMode::Sparse, torch::kCPU);
  const torch::Tensor rows = batch.neighbors.at({3, 1});
  torch::NoGradGuard noGrad;
  const torch::Tensor x = torch::rand({rows.size(0), 16}), w = torch::randn({16, 16, 3, 3, 3});
  for (auto _ : state)
    benchmark::DoNotOptimize(sparseConvolution(x, w, rows, state.range(0) == 0).sum().item<float>());
  state.SetLabel(std::string(state.range(0) == 0 ? "gather + GEMM" : "tap sums") + ", " +
                 std::to_string(rows.size(0)) + " voxels");
  at::set_num_threads(sagrid::defaultThreadCount());
}
BENCHMARK(BM_SparseConvolutionLayer)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

void BM_SparseTrainStep(benchmark::State& state) {
  configureTorchRuntime();
  const auto object = boxSurface();
  const auto shape = shapeFor(kArchitectures[state.range(0)]);
  SAGridNet net(shape);
  net->train();
  for (auto _ : state) {
    const auto batch = makeNetworkBatch({&object}, shape, ExecutionMode::Sparse, torch::kCPU);
    auto loss = net->forward(batch, ExecutionMode::Sparse).mean();
    loss.backward();
    benchmark::DoNotOptimize(loss.item<float>());
  }
  state.SetLabel(kArchitectures[state.range(0)]);
}
BENCHMARK(BM_SparseTrainStep)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

void BM_NeighborTables(benchmark::State& state) {
  const auto object = boxSurface();
  const auto shape = shapeFor(kDefaultArchitecture);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        makeNetworkBatch({&object}, shape, ExecutionMode::Sparse, torch::kCPU));
}
BENCHMARK(BM_NeighborTables)->Unit(benchmark::kMillisecond);

}  // namespace
