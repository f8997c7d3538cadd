#include "core/model/sagrid_network.h"

#include <gtest/gtest.h>

#include <random>

#include "core/common/error.h"

namespace sagrid::model {
namespace {

// A random blob of occupied voxels with random features, deterministic per seed.
NetworkObject randomObject(int resolution, int channels, int descriptorSize, unsigned seed,
                           double fill = 0.3) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  std::bernoulli_distribution occupied(fill);
  NetworkObject o;
  for (int i = 0; i < resolution; ++i)
    for (int j = 0; j < resolution; ++j)
      for (int k = 0; k < resolution; ++k)
        if (occupied(rng)) o.voxels.push_back({i, j, k});
  for (std::size_t v = 0; v < o.voxels.size() * channels; ++v) o.features.push_back(value(rng));
  for (int d = 0; d < descriptorSize; ++d) o.descriptor.push_back(value(rng));
  return o;
}

NetworkShape smallShape() {
  NetworkShape shape;
  shape.architecture = Architecture::parse("[3,1,8],[3,2,6,2],[3,1,4]");
  shape.featureChannels = 5;
  shape.descriptorSize = 7;
  shape.resolution = 8;
  return shape;
}

class FoldingTest : public ::testing::TestWithParam<ExecutionMode> {};

TEST_P(FoldingTest, FoldedDescriptorEqualsNaiveConcatenation) {
  torch::manual_seed(3);
  const NetworkShape shape = smallShape();
  SAGridNet net(shape);
  const auto a = randomObject(8, 5, 7, 1), b = randomObject(8, 5, 7, 2, 0.5);
  const auto batch = makeNetworkBatch({&a, &b}, shape, GetParam(), torch::kCPU);
  for (bool training : {false, true}) {
    net->train(training);
    torch::NoGradGuard noGrad;
    const auto folded = net->forward(batch, GetParam(), true);
    const auto naive = net->forward(batch, GetParam(), false);
    ASSERT_EQ(folded.size(0), static_cast<std::int64_t>(a.voxels.size() + b.voxels.size()));
    EXPECT_LT((folded - naive).abs().max().item<float>(), 1e-5f) << "training=" << training;
    // The descriptor does matter: changing it changes the output.
    auto c = b;
    for (auto& x : c.descriptor) x += 0.5f;
    const auto other = makeNetworkBatch({&a, &c}, shape, GetParam(), torch::kCPU);
    EXPECT_GT((net->forward(other, GetParam(), true) - folded).abs().max().item<float>(), 1e-4f);
  }
}

INSTANTIATE_TEST_SUITE_P(BothModes, FoldingTest,
                         ::testing::Values(ExecutionMode::Sparse, ExecutionMode::Dense));

TEST(SAGridNetwork, SparseEqualsDenseWhenEveryVoxelIsOccupied) {
  // With the whole grid occupied, submanifold sparse convolution is exactly dense convolution
  // with zero padding, so both modes (same weights) must agree in eval mode.
  torch::manual_seed(5);
  const NetworkShape shape = smallShape();
  SAGridNet net(shape);
  net->eval();
  const auto full = randomObject(8, 5, 7, 4, 1.0);
  ASSERT_EQ(full.voxels.size(), 512u);
  torch::NoGradGuard noGrad;
  const auto sparse = net->forward(
      makeNetworkBatch({&full}, shape, ExecutionMode::Sparse, torch::kCPU), ExecutionMode::Sparse);
  const auto dense = net->forward(
      makeNetworkBatch({&full}, shape, ExecutionMode::Dense, torch::kCPU), ExecutionMode::Dense);
  EXPECT_LT((sparse - dense).abs().max().item<float>(), 1e-5f);
}

TEST(SAGridNetwork, SparseOutputIgnoresUnoccupiedNeighboursFeatures) {
  // Submanifold: the output at a voxel depends only on occupied voxels within the receptive field.
  torch::manual_seed(6);
  const NetworkShape shape = smallShape();
  SAGridNet net(shape);
  net->eval();
  NetworkObject far;
  far.voxels = {{0, 0, 0}, {7, 7, 7}};
  far.features.assign(2 * 5, 0.3f);
  far.descriptor.assign(7, 0.1f);
  auto changed = far;
  for (int c = 0; c < 5; ++c) changed.features[5 + c] = -2.0f;
  torch::NoGradGuard noGrad;
  const auto y0 = net->forward(makeNetworkBatch({&far}, shape, ExecutionMode::Sparse, torch::kCPU),
                               ExecutionMode::Sparse);
  const auto y1 =
      net->forward(makeNetworkBatch({&changed}, shape, ExecutionMode::Sparse, torch::kCPU),
                   ExecutionMode::Sparse);
  EXPECT_FLOAT_EQ(y0[0].item<float>(), y1[0].item<float>());
  EXPECT_NE(y0[1].item<float>(), y1[1].item<float>());
}

TEST(SAGridNetwork, SparseConvolutionForwardAndBackwardEqualAutogradReference) {
  torch::manual_seed(8);
  for (int dilation : {1, 2}) {
    const auto object = randomObject(8, 5, 7, 9, 0.4);
    NetworkShape shape = smallShape();
    const auto batch = makeNetworkBatch({&object}, shape, ExecutionMode::Sparse, torch::kCPU);
    const torch::Tensor rows = batch.neighbors.at({3, dilation});
    const auto n = static_cast<std::int64_t>(object.voxels.size());
    torch::Tensor grads[2][2], outputs[2];
    const torch::Tensor x0 = torch::randn({n, 6}), w0 = torch::randn({4, 6, 3, 3, 3}),
                        g = torch::randn({n, 4});
    for (int reference = 0; reference < 2; ++reference) {
      torch::Tensor x = x0.clone().requires_grad_(true), w = w0.clone().requires_grad_(true);
      const torch::Tensor y = outputs[reference] = sparseConvolution(x, w, rows, reference == 1);
      (y * g).sum().backward();
      grads[reference][0] = x.grad();
      grads[reference][1] = w.grad();
    }
    // The forward pass (each tap's products added per voxel) against the gather and one GEMM.
    EXPECT_LT((outputs[0] - outputs[1]).abs().max().item<float>(), 1e-4f)
        << "dilation " << dilation;
    EXPECT_GT(outputs[0].abs().max().item<float>(), 0.1f);
    EXPECT_LT((grads[0][0] - grads[1][0]).abs().max().item<float>(), 1e-4f)
        << "dilation " << dilation;
    EXPECT_LT((grads[0][1] - grads[1][1]).abs().max().item<float>(), 1e-3f)
        << "dilation " << dilation;
    EXPECT_GT(grads[0][0].abs().max().item<float>(), 0.1f);
  }
}

TEST(SAGridNetwork, RejectsWrongFeatureAndDescriptorSizes) {
  const NetworkShape shape = smallShape();
  auto o = randomObject(8, 4, 7, 1);
  EXPECT_THROW(makeNetworkBatch({&o}, shape, ExecutionMode::Sparse, torch::kCPU), ModelError);
  auto p = randomObject(8, 5, 3, 1);
  EXPECT_THROW(makeNetworkBatch({&p}, shape, ExecutionMode::Sparse, torch::kCPU), ModelError);
}

TEST(SAGridNetwork, MacCountMatchesHandCount) {
  NetworkShape shape;
  shape.architecture = Architecture::parse("[3,1,4],[1,0,2]");
  shape.featureChannels = 2;
  shape.descriptorSize = 3;
  shape.resolution = 4;
  // Sparse, 10 voxels, folded: 10*27*3*4 + 27*4*(3+10) + 10*1*4*2 + head 10*2.
  EXPECT_DOUBLE_EQ(forwardMacs(shape, ExecutionMode::Sparse, 10),
                   10 * 27 * 3 * 4 + 27 * 4 * 13 + 10 * 4 * 2 + 10 * 2);
  // Dense, naive: 64 sites * 27 * 6 * 4 + 64 * 4 * 2 + 64 * 2.
  EXPECT_DOUBLE_EQ(forwardMacs(shape, ExecutionMode::Dense, 10, false),
                   64.0 * 27 * 6 * 4 + 64 * 4 * 2 + 64 * 2);
  // The paper's CNN-1 on TRELLIS features (8 channels + mask + 1024-d DINOv2), dense 64^3, naive
  // concatenation: 12.36 TMAC per forward pass; folding the descriptor saves 60 % of it.
  NetworkShape cnn1;
  cnn1.architecture = Architecture::parse(kPaperCnn1Architecture);
  cnn1.featureChannels = 8;
  cnn1.descriptorSize = 1024;
  cnn1.resolution = 64;
  EXPECT_NEAR(forwardMacs(cnn1, ExecutionMode::Dense, 0, false) / 1e9, 12357.46, 0.01);
  EXPECT_NEAR(forwardMacs(cnn1, ExecutionMode::Dense, 0, true) / 1e9, 4943.03, 0.01);
}

}  // namespace
}  // namespace sagrid::model
