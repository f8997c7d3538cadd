// The buffers of one rendered view: shaded RGB on a black background, albedo, z-depth, world
// normal and coverage mask. Row-major, top row first (image v grows downwards, as OpenCV).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

namespace sagrid {

constexpr float kBackgroundDepth = std::numeric_limits<float>::infinity();

struct RenderedView {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;     // 3 per pixel, albedo x headlight shading, 0 on background
  std::vector<float> albedo;  // 3 per pixel, unshaded surface colour, 0 on background
  std::vector<float> depth;   // z-depth along the optical axis, kBackgroundDepth on background
  std::vector<float> normal;  // 3 per pixel, unit world-space normal facing the camera, 0 on bg
  std::vector<std::uint8_t> mask;  // 1 where the object covers the pixel centre

  std::size_t pixelCount() const { return static_cast<std::size_t>(width) * height; }
  void resize(int w, int h) {
    width = w;
    height = h;
    rgb.resize(pixelCount() * 3);
    albedo.resize(pixelCount() * 3);
    depth.resize(pixelCount());
    normal.resize(pixelCount() * 3);
    mask.resize(pixelCount());
  }
};

}  // namespace sagrid
