#include "core/io/json_file.h"

#include "core/common/error.h"
#include "core/common/utf8.h"

namespace sagrid {

namespace {

// Nesting depth of brackets outside strings, stopping at the first level above kMaxJsonDepth.
// Malformed text is left to the parser, which says where it is wrong.
void checkDepth(std::string_view text, const std::filesystem::path& source) {
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) {
        throw FileError(source, "nests arrays and objects more than " +
                                    std::to_string(kMaxJsonDepth) + " levels deep (at byte " +
                                    std::to_string(i) + ")");
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace

nlohmann::json parseJsonDocument(std::string_view text, const std::filesystem::path& source) {
  if (text.empty()) throw FileError(source, "is empty (expected a JSON document)");
  if (auto bad = firstInvalidUtf8(text)) {
    throw FileError(source, "is not valid UTF-8 (bad byte at offset " + std::to_string(*bad) + ")");
  }
  checkDepth(text, source);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    // nlohmann's messages start "[json.exception.parse_error.101] "; out_of_range.406 is a
    // number too large for a double (1e400).
    const std::string what = e.what();
    const auto start = what.find("] ");
    throw FileError(source, "is not valid JSON: " +
                                (start == std::string::npos ? what : what.substr(start + 2)));
  }
}

nlohmann::json readJsonFile(const std::filesystem::path& path, std::uint64_t maxBytes) {
  return parseJsonDocument(readFileBytes(path, maxBytes), path);
}

}  // namespace sagrid
