#include <torch/script.h>
#include <torch/torch.h>

#include "core/common/error.h"
#include "core/common/thread_count.h"
#include "core/features/dinov2_encoder.h"
#include "core/render/multiview_renderer.h"

namespace sagrid {

struct Dinov2Encoder::Impl {
  torch::jit::script::Module module;
};

namespace {
std::string shapeText(const at::Tensor& t) {
  std::string s = "[";
  for (int64_t d = 0; d < t.dim(); ++d) s += (d ? ", " : "") + std::to_string(t.size(d));
  return s + "]";
}
}  // namespace

Dinov2Encoder::Dinov2Encoder(const std::filesystem::path& modelFile, int inputSize, int channels)
    : m_impl(std::make_unique<Impl>()),
      m_file(modelFile),
      m_inputSize(inputSize),
      m_channels(channels) {
  if (inputSize % kDinov2PatchSize != 0) {
    throw InvalidArgument("DINOv2 input size must be a multiple of 14, got " +
                          std::to_string(inputSize));
  }
  if (!std::filesystem::is_regular_file(modelFile)) {
    throw FileError(modelFile,
                    "DINOv2 TorchScript model not found (export it with "
                    "packaging/python/export_dinov2.py)");
  }
  try {
    m_impl->module = torch::jit::load(modelFile.string(), torch::kCPU);
    m_impl->module.eval();
  } catch (const c10::Error& e) {
    throw FileError(modelFile,
                    std::string("not a loadable TorchScript file: ") + e.what_without_backtrace());
  }
  at::set_num_threads(defaultThreadCount());
}

Dinov2Encoder::~Dinov2Encoder() = default;

void Dinov2Encoder::encode(const std::vector<const RenderedView*>& views,
                           const std::vector<const ViewCamera*>& /*cameras*/,
                           std::vector<FeatureMap>& out) {
  const int64_t batch = static_cast<int64_t>(views.size());
  out.resize(views.size());
  if (batch == 0) return;
  const int s = m_inputSize;
  at::Tensor input = torch::empty({batch, 3, s, s}, torch::kFloat32);
  auto acc = input.accessor<float, 4>();
  for (int64_t b = 0; b < batch; ++b) {
    const RenderedView& v = *views[b];
    if (v.width != s || v.height != s) {
      throw InvalidArgument("DINOv2 expects " + std::to_string(s) + "x" + std::to_string(s) +
                            " views, got " + std::to_string(v.width) + "x" +
                            std::to_string(v.height));
    }
    for (int y = 0; y < s; ++y) {
      for (int x = 0; x < s; ++x) {
        const float* rgb = &v.rgb[(static_cast<std::size_t>(y) * s + x) * 3];
        for (int c = 0; c < 3; ++c) acc[b][c][y][x] = (rgb[c] - kImageNetMean[c]) / kImageNetStd[c];
      }
    }
  }
  at::Tensor tokens;
  try {
    torch::NoGradGuard noGrad;
    const c10::IValue result = m_impl->module.forward({input});
    if (!result.isTensor()) {
      throw ModelError(m_file.string() + ": DINOv2 model must return one tensor [" +
                       std::to_string(batch) + ", " + std::to_string(patchGrid() * patchGrid()) +
                       ", " + std::to_string(m_channels) + "] (pre-norm patch tokens), got " +
                       result.tagKind());
    }
    tokens = result.toTensor().to(torch::kFloat32).contiguous();
  } catch (const c10::Error& e) {
    throw ModelError(m_file.string() + ": DINOv2 model failed on input [" + std::to_string(batch) +
                     ", 3, " + std::to_string(s) + ", " + std::to_string(s) +
                     "]: " + e.what_without_backtrace());
  }
  const int g = patchGrid();
  if (tokens.dim() != 3 || tokens.size(0) != batch || tokens.size(1) != g * g ||
      tokens.size(2) != m_channels) {
    throw ModelError(m_file.string() + ": DINOv2 model returned " + shapeText(tokens) +
                     ", expected [" + std::to_string(batch) + ", " + std::to_string(g * g) + ", " +
                     std::to_string(m_channels) +
                     "] (pre-norm patch tokens of dinov2_vitl14_reg without CLS/register tokens; "
                     "export with packaging/python/export_dinov2.py)");
  }
  for (int64_t b = 0; b < batch; ++b) {
    FeatureMap& map = out[b];
    map.resize(g, g, m_channels);
    // Tokens are row-major patches (TRELLIS reshapes them to [C, 37, 37]): token index y * g + x.
    const float* src = tokens[b].data_ptr<float>();
    std::copy(src, src + static_cast<std::size_t>(g) * g * m_channels, map.values.begin());
  }
}

}  // namespace sagrid
