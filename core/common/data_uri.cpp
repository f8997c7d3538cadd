#include "core/common/data_uri.h"

#include <cctype>

#include "core/common/error.h"

namespace sagrid {
namespace {

constexpr std::string_view kDataScheme = "data:";

// -1 for a byte outside the base64 alphabet.
int base64Value(unsigned char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+' || c == '-') return 62;  // '-' and '_': the URL-safe alphabet some exporters use
  if (c == '/' || c == '_') return 63;
  return -1;
}

std::string base64Decoded(std::string_view text) {
  std::string out;
  out.reserve(text.size() / 4 * 3);
  unsigned accumulated = 0;
  int bits = 0;
  std::size_t padding = 0;
  for (const unsigned char c : text) {
    if (std::isspace(c)) continue;
    if (c == '=') {
      ++padding;
      continue;
    }
    const int value = base64Value(c);
    if (value < 0 || padding > 0) throw InvalidArgument("malformed base64 in a data URI");
    accumulated = (accumulated << 6) | static_cast<unsigned>(value);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((accumulated >> bits) & 0xFFu);
    }
  }
  if (padding > 2) throw InvalidArgument("malformed base64 in a data URI");
  return out;
}

}  // namespace

std::optional<std::string> dataUriBytes(std::string_view uri) {
  if (uri.substr(0, kDataScheme.size()) != kDataScheme) return std::nullopt;
  const std::size_t comma = uri.find(',');
  if (comma == std::string_view::npos) throw InvalidArgument("a data URI without ','");
  const std::string_view header = uri.substr(kDataScheme.size(), comma - kDataScheme.size());
  constexpr std::string_view kBase64 = ";base64";
  if (header.size() < kBase64.size() || header.substr(header.size() - kBase64.size()) != kBase64) {
    throw InvalidArgument("a data URI that is not base64 (glTF embeds base64 only)");
  }
  return base64Decoded(uri.substr(comma + 1));
}

std::string dataUriMediaType(std::string_view uri) {
  if (uri.substr(0, kDataScheme.size()) != kDataScheme) return {};
  const std::size_t end = uri.find_first_of(";,");
  if (end == std::string_view::npos) return {};
  return std::string(uri.substr(kDataScheme.size(), end - kDataScheme.size()));
}

std::string percentDecoded(std::string_view text) {
  auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size()) {
      const int hi = hex(text[i + 1]), lo = hex(text[i + 2]);
      if (hi >= 0 && lo >= 0) {
        out += static_cast<char>(hi * 16 + lo);
        i += 2;
        continue;
      }
    }
    out += text[i];
  }
  return out;
}

}  // namespace sagrid
