// Texture images as mesh files carry them: PNG, JPEG, BMP, TGA (stb_image) and WebP (libwebp,
// for glTF's EXT_texture_webp and the image/webp images in-the-wild GLBs embed), decoded to RGBA8.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include "core/mesh/mesh.h"

namespace sagrid {

// The image, or nullopt when the bytes are no image either library decodes.
std::optional<Texture> decodeTexture(const unsigned char* bytes, std::size_t size);

// True for bytes that start like a WebP file ("RIFF....WEBP").
bool isWebp(std::string_view bytes);

// "image/png", "image/jpeg" or "image/webp" from the bytes' signature; empty for anything else.
const char* imageMimeType(std::string_view bytes);

}  // namespace sagrid
