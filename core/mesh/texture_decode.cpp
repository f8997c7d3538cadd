#include "core/mesh/texture_decode.h"

#include <stb_image.h>
#include <webp/decode.h>

#include <climits>

namespace sagrid {

bool isWebp(std::string_view bytes) {
  return bytes.size() >= 12 && bytes.substr(0, 4) == "RIFF" && bytes.substr(8, 4) == "WEBP";
}

const char* imageMimeType(std::string_view bytes) {
  if (bytes.size() >= 8 && bytes.substr(0, 8) == "\x89PNG\r\n\x1a\n") return "image/png";
  if (bytes.size() >= 3 && bytes.substr(0, 3) == "\xFF\xD8\xFF") return "image/jpeg";
  if (isWebp(bytes)) return "image/webp";
  return "";
}

std::optional<Texture> decodeTexture(const unsigned char* bytes, std::size_t size) {
  if (size == 0 || size > static_cast<std::size_t>(INT_MAX)) return std::nullopt;
  const bool webp = isWebp(std::string_view(reinterpret_cast<const char*>(bytes), size));
  int w = 0, h = 0, channels = 0;
  std::uint8_t* pixels = webp ? WebPDecodeRGBA(bytes, size, &w, &h)
                              : stbi_load_from_memory(bytes, static_cast<int>(size), &w, &h, &channels, 4);
  if (!pixels) return std::nullopt;
  Texture texture;
  texture.width = w;
  texture.height = h;
  texture.rgba.assign(pixels, pixels + static_cast<std::size_t>(w) * h * 4);
  if (webp) WebPFree(pixels);
  else stbi_image_free(pixels);
  return texture;
}

}  // namespace sagrid
