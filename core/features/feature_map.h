// A 2D feature map covering one whole view: per-pixel (render buffers) or per-patch (DINOv2's
// 37x37 tokens) features, sampled bilinearly at projected voxel centres.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sagrid {

struct FeatureMap {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> values;  // height * width * channels, rows top to bottom, channel fastest

  void resize(int w, int h, int c) {
    width = w;
    height = h;
    channels = c;
    values.assign(static_cast<std::size_t>(w) * h * c, 0.0f);
  }
  float* at(int x, int y) {
    return values.data() + (static_cast<std::size_t>(y) * width + x) * channels;
  }
  const float* at(int x, int y) const {
    return values.data() + (static_cast<std::size_t>(y) * width + x) * channels;
  }
};

// Adds weight * (bilinear sample at normalized image coordinates uv) to out[0..channels), exactly
// as torch.nn.functional.grid_sample(mode="bilinear", align_corners=False, padding_mode="zeros")
// with grid = uv * 2 - 1: texel centres at (x + 0.5) / width, taps outside the map count as 0.
void addBilinearSample(const FeatureMap& map, const Eigen::Vector2f& uv, float weight, float* out);

}  // namespace sagrid
