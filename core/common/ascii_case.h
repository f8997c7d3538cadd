// ASCII lower case for what the product compares case-blind: file extensions, keywords of text
// formats, category names. Bytes from 0x80 (UTF-8) pass unchanged, whatever the locale.
#pragma once

#include <filesystem>
#include <string>

namespace sagrid {

inline std::string asciiLower(std::string text) {
  for (char& c : text)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return text;
}

// The path's extension, its dot included, in lower case: "Sink.OBJ" -> ".obj".
inline std::string lowerExtension(const std::filesystem::path& path) {
  return asciiLower(path.extension().string());
}

}  // namespace sagrid
