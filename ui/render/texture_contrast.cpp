#include "ui/render/texture_contrast.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/mesh/mesh.h"

namespace sagrid::ui {

namespace {
// sRGB-encoded byte to linear light (the decode GL_SRGB8_ALPHA8 samples with).
float linear(std::uint8_t byte) {
  const float c = float(byte) / 255.0f;
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
}  // namespace

LuminanceRange luminanceRange(const Texture& texture, float lowShare, float highShare) {
  const std::size_t texels = std::size_t(std::max(0, texture.width)) * std::size_t(std::max(0, texture.height));
  if (texels == 0 || texture.rgba.size() < texels * 4) return {};
  std::array<float, 256> decode{};
  for (int b = 0; b < 256; ++b) decode[std::size_t(b)] = linear(std::uint8_t(b));
  // Every texel up to kMostSampled, an even stride of them beyond: the range is read each time an
  // object opens, and a 4096^2 texture's quantiles are the same to the eye from 65,536 texels.
  constexpr std::size_t kMostSampled = 65536;
  const std::size_t stride = (texels + kMostSampled - 1) / kMostSampled;
  std::vector<float> luminance;
  luminance.reserve(texels / stride + 1);
  for (std::size_t i = 0; i < texels; i += stride) {
    const std::uint8_t* p = &texture.rgba[4 * i];
    luminance.push_back(0.2126f * decode[p[0]] + 0.7152f * decode[p[1]] + 0.0722f * decode[p[2]]);
  }
  const std::size_t n = luminance.size();
  auto quantile = [&](float share) {
    const std::size_t k = std::min(n - 1, std::size_t(std::clamp(share, 0.0f, 1.0f) * float(n - 1)));
    std::nth_element(luminance.begin(), luminance.begin() + std::ptrdiff_t(k), luminance.end());
    return luminance[k];
  };
  LuminanceRange range{quantile(lowShare), quantile(highShare)};
  constexpr float kLeast = 1.0f / 255.0f;
  if (range.high - range.low < kLeast) {
    const float middle = 0.5f * (range.low + range.high);
    range = {std::max(0.0f, middle - 0.5f * kLeast), std::max(0.0f, middle - 0.5f * kLeast) + kLeast};
  }
  return range;
}

}  // namespace sagrid::ui
