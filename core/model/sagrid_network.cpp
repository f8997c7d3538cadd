#include "core/model/sagrid_network.h"

#include <cmath>

#include <ATen/Parallel.h>

#include "core/common/error.h"
#include "core/model/sparse_neighbors.h"

namespace sagrid::model {
namespace {

int taps(const ConvLayerSpec& l) { return l.kernel * l.kernel * l.kernel; }

// Weight (Cout, Cin, k, k, k) -> (taps * Cin, Cout), row (t * Cin + c), matching the gathered
// input laid out (voxel, tap, channel).
torch::Tensor tapMatrix(const torch::Tensor& weight) {
  const auto cout = weight.size(0), cin = weight.size(1);
  const auto t = weight.size(2) * weight.size(3) * weight.size(4);
  return weight.permute({2, 3, 4, 1, 0}).reshape({t * cin, cout});
}

// Per object o and tap t: b[o][t] = W_t[:, descriptor] . d_o, as (B, taps, Cout).
torch::Tensor descriptorTapVectors(const torch::Tensor& weight, std::int64_t firstDescriptorChannel,
                                   const torch::Tensor& descriptors) {
  const auto d = descriptors.size(1);
  const auto cout = weight.size(0);
  const auto t = weight.size(2) * weight.size(3) * weight.size(4);
  torch::Tensor wd = weight
                         .narrow(1, firstDescriptorChannel, d)  // (Cout, D, k, k, k)
                         .permute({2, 3, 4, 0, 1})
                         .reshape({t * cout, d});  // (T * Cout, D)
  return descriptors.mm(wd.t()).view({descriptors.size(0), t, cout});
}

torch::Tensor gatherTaps(const torch::Tensor& x, const torch::Tensor& rows) {
  const std::int64_t n = rows.size(0);
  torch::Tensor padded = torch::cat({x, torch::zeros({1, x.size(1)}, x.options())}, 0);
  return padded.index_select(0, rows.reshape({-1})).view({n, -1});
}

// y[v] = sum_t x[rows(v, t)] W_t with W = (taps * Cin, Cout) as tapMatrix lays it out. On the CPU
// every voxel's product with every tap comes first (one GEMM: (N, Cin) by (Cin, taps * Cout)),
// then each voxel adds its neighbours' rows of it, taps in order: the gathered (N, taps * Cin)
// input is never formed, nor packed again by the GEMM. Elsewhere: the gather and one GEMM.
torch::Tensor tapSum(const torch::Tensor& x, const torch::Tensor& rows, const torch::Tensor& w) {
  const std::int64_t n = rows.size(0), taps = rows.size(1), cin = x.size(1), cout = w.size(1);
  if (!x.is_cpu() || x.scalar_type() != torch::kFloat || rows.scalar_type() != torch::kLong)
    return gatherTaps(x, rows).mm(w);
  const torch::Tensor perTap =
      x.contiguous().mm(w.view({taps, cin, cout}).permute({1, 0, 2}).reshape({cin, taps * cout}));
  const torch::Tensor index = rows.contiguous();
  torch::Tensor y = torch::zeros({n, cout}, x.options());
  const float* z = perTap.data_ptr<float>();
  const std::int64_t* r = index.data_ptr<std::int64_t>();
  float* out = y.data_ptr<float>();
  const std::int64_t present = x.size(0);
  at::parallel_for(0, n, 1024, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) {
      float* sum = out + v * cout;
      for (std::int64_t t = 0; t < taps; ++t) {
        const std::int64_t u = r[v * taps + t];
        if (u >= present) continue;  // an absent neighbour: the zero row
        const float* term = z + (u * taps + t) * cout;
        for (std::int64_t o = 0; o < cout; ++o) sum[o] += term[o];
      }
    }
  });
  return y;
}

class SparseConvolutionFunction : public torch::autograd::Function<SparseConvolutionFunction> {
 public:
  static torch::Tensor forward(torch::autograd::AutogradContext* ctx, const torch::Tensor& x,
                               const torch::Tensor& weight, const torch::Tensor& rows) {
    ctx->save_for_backward({x, weight, rows});
    return tapSum(x, rows, tapMatrix(weight));
  }

  static torch::autograd::tensor_list backward(torch::autograd::AutogradContext* ctx,
                                               torch::autograd::tensor_list gradOutputs) {
    const auto saved = ctx->get_saved_variables();
    const torch::Tensor& x = saved[0];
    const torch::Tensor& weight = saved[1];
    const torch::Tensor& rows = saved[2];
    const torch::Tensor grad = gradOutputs[0].contiguous();
    const auto cout = weight.size(0), cin = weight.size(1);
    const auto taps = weight.size(2) * weight.size(3) * weight.size(4);
    torch::Tensor gradX, gradW;
    if (ctx->needs_input_grad(0)) {
      // x[u] reaches y[v] through tap t exactly when v is u's neighbour through the mirrored tap.
      const torch::Tensor back = weight.permute({2, 3, 4, 0, 1}).reshape({taps * cout, cin});
      gradX = tapSum(grad, rows.flip({1}), back);
    }
    if (ctx->needs_input_grad(1)) {
      // Recomputing the gathered input is cheaper than keeping it alive between passes.
      gradW = gatherTaps(x, rows)
                  .t()
                  .mm(grad)  // (taps * Cin, Cout)
                  .view({weight.size(2), weight.size(3), weight.size(4), cin, cout})
                  .permute({4, 3, 0, 1, 2})
                  .contiguous();
    }
    return {gradX, gradW, torch::Tensor()};
  }
};

}  // namespace

torch::Tensor sparseConvolution(const torch::Tensor& x, const torch::Tensor& weight,
                                const torch::Tensor& rows, bool reference) {
  if (reference) return gatherTaps(x, rows).mm(tapMatrix(weight));
  return SparseConvolutionFunction::apply(x, weight, rows);
}

NetworkBatch makeNetworkBatch(const std::vector<const NetworkObject*>& objects,
                              const NetworkShape& shape, ExecutionMode mode,
                              const torch::Device& device) {
  if (objects.empty()) throw InvalidArgument("network batch: no objects");
  NetworkBatch batch;
  const int c = shape.featureChannels;
  const int d = shape.descriptorSize;
  const std::int64_t r = shape.resolution;
  batch.offsets.push_back(0);
  for (const auto* o : objects) {
    if (o->voxels.empty()) throw InvalidArgument("network batch: an object has no occupied voxels");
    if (o->features.size() != o->voxels.size() * static_cast<std::size_t>(c))
      throw ModelError("network batch: " + std::to_string(o->features.size()) +
                       " feature values for " + std::to_string(o->voxels.size()) + " voxels x " +
                       std::to_string(c) + " channels");
    if (o->descriptor.size() != static_cast<std::size_t>(d))
      throw ModelError("network batch: descriptor has " + std::to_string(o->descriptor.size()) +
                       " values, the model expects " + std::to_string(d));
    batch.offsets.push_back(batch.offsets.back() + static_cast<std::int64_t>(o->voxels.size()));
  }
  const std::int64_t n = batch.offsets.back();
  const auto b = static_cast<std::int64_t>(objects.size());

  std::vector<float> input(static_cast<std::size_t>(n) * (c + 1));
  std::vector<float> descriptors(static_cast<std::size_t>(b) * d);
  std::vector<std::int64_t> denseIndex(static_cast<std::size_t>(n));
  for (std::int64_t o = 0; o < b; ++o) {
    const auto* obj = objects[o];
    for (std::size_t v = 0; v < obj->voxels.size(); ++v) {
      const std::size_t row = batch.offsets[o] + v;
      std::copy_n(obj->features.data() + v * c, c, input.data() + row * (c + 1));
      input[row * (c + 1) + c] = 1.0f;
      const auto& p = obj->voxels[v];
      denseIndex[row] = o * r * r * r + (p.i * r + p.j) * r + p.k;
    }
    std::copy(obj->descriptor.begin(), obj->descriptor.end(), descriptors.data() + o * d);
  }
  const auto floatOptions = torch::TensorOptions().dtype(torch::kFloat32);
  const auto longOptions = torch::TensorOptions().dtype(torch::kInt64);
  batch.features = torch::from_blob(input.data(), {n, c + 1}, floatOptions).clone().to(device);
  batch.descriptors = torch::from_blob(descriptors.data(), {b, d}, floatOptions).clone().to(device);
  batch.denseIndex = torch::from_blob(denseIndex.data(), {n}, longOptions).clone().to(device);

  // Sparse layers need neighbour rows per (kernel, dilation); the first layer's table also gives
  // the per-voxel tap presence for descriptor folding in sparse mode.
  if (mode == ExecutionMode::Sparse) {
    for (const auto& layer : shape.architecture.layers) {
      const auto key = std::make_pair(layer.kernel, layer.dilation);
      if (batch.neighbors.count(key)) continue;
      const int t = taps(layer);
      std::vector<std::int64_t> rows(static_cast<std::size_t>(n) * t);
      for (std::int64_t o = 0; o < b; ++o) {
        const auto table = buildNeighborTable(objects[o]->voxels, shape.resolution, layer.kernel,
                                              layer.dilation, -1);
        std::int64_t* out = rows.data() + batch.offsets[o] * t;
        for (std::size_t e = 0; e < table.rows.size(); ++e)
          out[e] = table.rows[e] < 0 ? n : table.rows[e] + batch.offsets[o];
      }
      batch.neighbors[key] = torch::from_blob(rows.data(), {n, t}, longOptions).clone().to(device);
    }
  }
  return batch;
}

SAGridNetImpl::SAGridNetImpl(const NetworkShape& shape) : m_shape(shape) {
  if (shape.architecture.layers.empty()) throw InvalidArgument("architecture has no layers");
  if (shape.featureChannels < 0 || shape.descriptorSize < 0 || shape.resolution < 4)
    throw InvalidArgument("network shape: invalid channel counts or grid size");
  std::int64_t cin = shape.inputChannels();
  for (std::size_t i = 0; i < shape.architecture.layers.size(); ++i) {
    const auto& l = shape.architecture.layers[i];
    const std::int64_t cout = l.outChannels;
    const std::string p = "layer" + std::to_string(i) + "_";
    // He initialisation for conv + ReLU.
    const double stddev = std::sqrt(2.0 / static_cast<double>(cin * taps(l)));
    m_convWeights.push_back(register_parameter(
        p + "weight", torch::randn({cout, cin, l.kernel, l.kernel, l.kernel}) * stddev));
    m_bnWeights.push_back(register_parameter(p + "bn_weight", torch::ones({cout})));
    m_bnBiases.push_back(register_parameter(p + "bn_bias", torch::zeros({cout})));
    m_bnMeans.push_back(register_buffer(p + "bn_running_mean", torch::zeros({cout})));
    m_bnVars.push_back(register_buffer(p + "bn_running_var", torch::ones({cout})));
    cin = cout;
  }
  // Unit-gain head: with a small head (0.1 / sqrt(C)) the last layer's units get tiny gradients,
  // many die, and the output floors near the prior at small parts (measured on an overfit run).
  m_headWeight = register_parameter("head_weight", torch::randn({1, cin}) / std::sqrt(cin));
  // Start near the typical target: log(1 + 0.25) ~ 0.22, softplus^-1(0.22) ~ -1.4.
  m_headBias = register_parameter("head_bias", torch::full({1}, -1.4));
}

torch::Tensor SAGridNetImpl::batchNormRelu(const torch::Tensor& x, std::size_t layer) {
  return torch::relu(torch::batch_norm(x, m_bnWeights[layer], m_bnBiases[layer], m_bnMeans[layer],
                                       m_bnVars[layer], is_training() && !m_frozenStatistics, 0.1, 1e-5,
                                       /*cudnn_enabled=*/true));
}

std::vector<torch::Tensor> SAGridNetImpl::lastLayerParameters() const {
  return {m_convWeights.back(), m_bnWeights.back(), m_bnBiases.back(), m_headWeight, m_headBias};
}

torch::Tensor SAGridNetImpl::forward(const NetworkBatch& batch, ExecutionMode mode,
                                     bool foldDescriptor) {
  if (batch.features.size(1) != m_shape.featureChannels + 1)
    throw ModelError("network input has " + std::to_string(batch.features.size(1) - 1) +
                     " feature channels, the model expects " +
                     std::to_string(m_shape.featureChannels));
  return mode == ExecutionMode::Sparse ? forwardSparse(batch, foldDescriptor)
                                       : forwardDense(batch, foldDescriptor);
}

torch::Tensor SAGridNetImpl::forwardSparse(const NetworkBatch& batch, bool fold) {
  const std::int64_t n = batch.voxelCount();
  const std::int64_t localChannels = m_shape.featureChannels + 1;
  torch::Tensor x = batch.features;
  if (!fold) {
    // Naive reference: the descriptor concatenated to every occupied voxel's input.
    std::vector<torch::Tensor> parts;
    for (int o = 0; o < batch.batchSize(); ++o) {
      const auto count = batch.offsets[o + 1] - batch.offsets[o];
      parts.push_back(batch.descriptors[o].unsqueeze(0).expand({count, m_shape.descriptorSize}));
    }
    x = torch::cat({x, torch::cat(parts, 0)}, 1);
  }
  for (std::size_t i = 0; i < m_convWeights.size(); ++i) {
    const auto& l = m_shape.architecture.layers[i];
    const torch::Tensor& rows = batch.neighbors.at({l.kernel, l.dilation});
    torch::Tensor weight = m_convWeights[i];
    if (i == 0 && fold) weight = weight.narrow(1, 0, localChannels);
    // Gather every tap's neighbour row (absent -> the appended zero row), one GEMM for all taps.
    torch::Tensor y = sparseConvolution(x, weight, rows);
    if (i == 0 && fold && m_shape.descriptorSize > 0) {
      torch::Tensor perTap = descriptorTapVectors(m_convWeights[0], localChannels,
                                                  batch.descriptors);  // (B, T, Cout)
      torch::Tensor present = rows.ne(n).to(x.scalar_type());          // (N, T)
      std::vector<torch::Tensor> parts;
      for (int o = 0; o < batch.batchSize(); ++o) {
        const auto begin = batch.offsets[o], count = batch.offsets[o + 1] - begin;
        parts.push_back(present.narrow(0, begin, count).mm(perTap[o]));
      }
      y = y + torch::cat(parts, 0);
    }
    x = batchNormRelu(y, i);
  }
  return torch::softplus(x.mm(m_headWeight.t()) + m_headBias).view({n});
}

torch::Tensor SAGridNetImpl::forwardDense(const NetworkBatch& batch, bool fold) {
  const std::int64_t b = batch.batchSize();
  const std::int64_t r = m_shape.resolution;
  const std::int64_t localChannels = m_shape.featureChannels + 1;
  const std::int64_t cIn = fold ? localChannels : m_shape.inputChannels();
  torch::Tensor flat = torch::zeros({b * r * r * r, cIn}, batch.features.options());
  torch::Tensor local = batch.features;
  if (!fold) {
    // Naive reference: the descriptor at every voxel of the grid, occupied or not.
    flat.narrow(1, localChannels, m_shape.descriptorSize)
        .copy_(batch.descriptors.unsqueeze(1)
                   .expand({b, r * r * r, m_shape.descriptorSize})
                   .reshape({b * r * r * r, m_shape.descriptorSize}));
  }
  flat.narrow(1, 0, localChannels).index_copy_(0, batch.denseIndex, local);
  torch::Tensor x = flat.view({b, r, r, r, cIn}).permute({0, 4, 1, 2, 3}).contiguous();
  for (std::size_t i = 0; i < m_convWeights.size(); ++i) {
    const auto& l = m_shape.architecture.layers[i];
    torch::Tensor weight = m_convWeights[i];
    if (i == 0 && fold) weight = weight.narrow(1, 0, localChannels);
    torch::Tensor y = torch::conv3d(x, weight, {}, 1, l.padding, l.dilation);
    if (i == 0 && fold && m_shape.descriptorSize > 0) {
      // Sum of b_t over the taps that land inside the grid = conv of the in-grid indicator with
      // the per-object tap vectors (grouped: one group per object).
      const std::int64_t cout = l.outChannels;
      torch::Tensor perTap = descriptorTapVectors(m_convWeights[0], localChannels,
                                                  batch.descriptors);  // (B, T, Cout)
      torch::Tensor kernel =
          perTap.permute({0, 2, 1}).reshape({b * cout, 1, l.kernel, l.kernel, l.kernel});
      torch::Tensor inside = torch::ones({1, b, r, r, r}, x.options());
      torch::Tensor shared = torch::conv3d(inside, kernel, {}, 1, l.padding, l.dilation, b);
      y = y + shared.view({b, cout, r, r, r});
    }
    x = batchNormRelu(y, i);
  }
  torch::Tensor head = torch::conv3d(x, m_headWeight.view({1, -1, 1, 1, 1}), m_headBias);
  return torch::softplus(head).reshape({-1}).index_select(0, batch.denseIndex);
}

double forwardMacs(const NetworkShape& shape, ExecutionMode mode, std::int64_t occupiedVoxels,
                   bool foldDescriptor) {
  const double sites = mode == ExecutionMode::Sparse
                           ? static_cast<double>(occupiedVoxels)
                           : std::pow(static_cast<double>(shape.resolution), 3);
  double macs = 0;
  double cin = foldDescriptor ? shape.featureChannels + 1 : shape.inputChannels();
  for (std::size_t i = 0; i < shape.architecture.layers.size(); ++i) {
    const auto& l = shape.architecture.layers[i];
    const double t = taps(l);
    macs += sites * t * cin * l.outChannels;
    if (i == 0 && foldDescriptor) macs += t * l.outChannels * (shape.descriptorSize + sites);
    cin = l.outChannels;
  }
  return macs + sites * cin;  // head
}

}  // namespace sagrid::model
