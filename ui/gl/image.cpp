#include "ui/gl/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/common/atomic_file.h"
#include "core/common/error.h"

namespace sagrid::ui {

namespace {
void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}
}  // namespace

void writePng(const std::filesystem::path& path, const RgbaImage& image) {
  if (image.width <= 0 || image.height <= 0) throw FileError(path, "cannot write an empty image");
  std::string bytes;
  if (!stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 4,
                              image.pixels.data(), image.width * 4)) {
    throw FileError(path, "PNG encoding failed");
  }
  writeFileAtomic(path, bytes);
}

RgbaImage readPng(const std::filesystem::path& path) {
  const std::string bytes = readFileBytes(path);
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<int>(bytes.size()), &w, &h, &channels, 4);
  if (!data) throw FileError(path, std::string("not a readable image: ") + stbi_failure_reason());
  RgbaImage image;
  image.width = w;
  image.height = h;
  image.pixels.assign(data, data + std::size_t(w) * h * 4);
  stbi_image_free(data);
  return image;
}

ImageDifference compareImages(const RgbaImage& expected, const RgbaImage& actual, int tolerance) {
  ImageDifference result;
  result.sameSize = expected.width == actual.width && expected.height == actual.height;
  if (!result.sameSize) return result;
  result.maxChannelDifference = 0;
  result.diff = expected;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const std::uint8_t* a = expected.at(x, y);
      const std::uint8_t* b = actual.at(x, y);
      int largest = 0;
      for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(int(a[c]) - int(b[c])));
      result.maxChannelDifference = std::max(result.maxChannelDifference, largest);
      std::uint8_t* d = result.diff.at(x, y);
      if (largest > tolerance) {
        ++result.differingPixels;
        d[0] = 255, d[1] = 0, d[2] = 0, d[3] = 255;
      } else {
        for (int c = 0; c < 3; ++c) d[c] = static_cast<std::uint8_t>(a[c] / 4);
        d[3] = 255;
      }
    }
  }
  result.differingShare =
      double(result.differingPixels) / double(std::size_t(expected.width) * expected.height);
  return result;
}

}  // namespace sagrid::ui
