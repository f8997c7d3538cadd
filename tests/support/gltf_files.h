// glTF files built in tests: a GLB of any JSON document and binary chunk, written as given (the
// document's buffers[] untouched, so a test can declare fallback or external buffers).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace sagrid::test {

std::string glbBytes(const nlohmann::json& document, const std::string& binary);

// `bytes` appended to `binary` at a 4-byte boundary; returns the byte offset it starts at.
std::size_t appendAligned(std::string& binary, const std::string& bytes);

// The bytes of a trivially copyable array.
template <typename T>
std::string bytesOf(const T* values, std::size_t count) {
  return std::string(reinterpret_cast<const char*>(values), count * sizeof(T));
}

}  // namespace sagrid::test
