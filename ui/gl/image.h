// RGBA8 images as the renderer reads them back, PNG in and out (stb), and the comparison used by
// image-baseline tests (per-pixel tolerance + share of differing pixels, with a diff image).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sagrid::ui {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 4, rows top to bottom

  const std::uint8_t* at(int x, int y) const {
    return pixels.data() + (std::size_t(y) * width + x) * 4;
  }
  std::uint8_t* at(int x, int y) { return pixels.data() + (std::size_t(y) * width + x) * 4; }
};

void writePng(const std::filesystem::path& path, const RgbaImage& image);  // atomic
RgbaImage readPng(const std::filesystem::path& path);                      // throws FileError

struct ImageDifference {
  bool sameSize = false;
  std::size_t differingPixels = 0;  // pixels whose largest channel difference exceeds the tolerance
  double differingShare = 1.0;      // differingPixels / pixel count
  int maxChannelDifference = 255;
  RgbaImage diff;  // differing pixels red over a dimmed copy of the expected image
};

ImageDifference compareImages(const RgbaImage& expected, const RgbaImage& actual, int tolerance);

}  // namespace sagrid::ui
