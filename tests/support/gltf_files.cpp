#include "support/gltf_files.h"

#include <cstdint>

namespace sagrid::test {

std::string glbBytes(const nlohmann::json& document, const std::string& binary) {
  std::string json = document.dump();
  while (json.size() % 4) json += ' ';
  std::string bin = binary;
  while (bin.size() % 4) bin += '\0';
  auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const auto total = static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size()));
  std::string out = "glTF" + u32(2) + u32(total) + u32(static_cast<std::uint32_t>(json.size())) + "JSON" + json;
  if (!bin.empty()) out += u32(static_cast<std::uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
  return out;
}

std::size_t appendAligned(std::string& binary, const std::string& bytes) {
  while (binary.size() % 4) binary += '\0';
  const std::size_t at = binary.size();
  binary += bytes;
  return at;
}

}  // namespace sagrid::test
