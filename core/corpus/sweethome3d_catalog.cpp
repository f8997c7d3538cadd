#include "core/corpus/sweethome3d_catalog.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <regex>

#include "core/common/ascii_case.h"
#include "core/common/error.h"
#include "core/common/sha256.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {

void appendUtf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

// Splits into logical lines: physical lines joined where one ends in an odd number of
// backslashes (the continuation's leading whitespace is dropped, as java.util.Properties does).
std::vector<std::pair<int, std::string>> logicalLines(std::string_view bytes) {
  std::vector<std::pair<int, std::string>> lines;
  std::string current;
  bool continuing = false;
  int number = 0, startNumber = 0;
  std::size_t at = 0;
  while (at <= bytes.size()) {
    std::size_t end = at;
    while (end < bytes.size() && bytes[end] != '\n' && bytes[end] != '\r') ++end;
    std::string_view line = bytes.substr(at, end - at);
    ++number;
    if (end < bytes.size() && bytes[end] == '\r' && end + 1 < bytes.size() &&
        bytes[end + 1] == '\n')
      ++end;
    at = end + 1;
    if (continuing) {
      std::size_t skip = 0;
      while (skip < line.size() && (line[skip] == ' ' || line[skip] == '\t' || line[skip] == '\f'))
        ++skip;
      line = line.substr(skip);
    } else {
      startNumber = number;
      std::size_t skip = 0;
      while (skip < line.size() && (line[skip] == ' ' || line[skip] == '\t' || line[skip] == '\f'))
        ++skip;
      if (skip == line.size() || line[skip] == '#' || line[skip] == '!') {
        if (end >= bytes.size()) break;
        continue;
      }
      line = line.substr(skip);
    }
    std::size_t backslashes = 0;
    while (backslashes < line.size() && line[line.size() - 1 - backslashes] == '\\') ++backslashes;
    if (backslashes % 2 == 1) {
      current += line.substr(0, line.size() - 1);
      continuing = true;
    } else {
      current += line;
      lines.emplace_back(startNumber, std::move(current));
      current.clear();
      continuing = false;
    }
    if (end >= bytes.size()) break;
  }
  if (continuing) lines.emplace_back(startNumber, std::move(current));
  return lines;
}

// Unescapes one key or value (ISO-8859-1 bytes) into UTF-8.
std::string unescape(std::string_view text, const fs::path& source, int line) {
  std::string out;
  std::uint32_t pendingHigh = 0;  // a UTF-16 high surrogate waiting for its low half
  auto flushHigh = [&] {
    if (pendingHigh) appendUtf8(out, 0xFFFD);
    pendingHigh = 0;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c != '\\' || i + 1 == text.size()) {
      flushHigh();
      if (c != '\\') appendUtf8(out, c);
      continue;
    }
    const char e = text[++i];
    if (e == 'u') {
      if (i + 4 >= text.size() ||
          !std::all_of(text.begin() + i + 1, text.begin() + i + 5,
                       [](char h) { return std::isxdigit(static_cast<unsigned char>(h)) != 0; })) {
        throw FileError(source, "line " + std::to_string(line) + ": malformed \\uXXXX escape");
      }
      const auto unit = static_cast<std::uint32_t>(
          std::strtoul(std::string(text.substr(i + 1, 4)).c_str(), nullptr, 16));
      i += 4;
      if (unit >= 0xD800 && unit < 0xDC00) {
        flushHigh();
        pendingHigh = unit;
      } else if (unit >= 0xDC00 && unit < 0xE000) {
        if (pendingHigh) {
          appendUtf8(out, 0x10000 + ((pendingHigh - 0xD800) << 10) + (unit - 0xDC00));
          pendingHigh = 0;
        } else {
          appendUtf8(out, 0xFFFD);
        }
      } else {
        flushHigh();
        appendUtf8(out, unit);
      }
      continue;
    }
    flushHigh();
    switch (e) {
      case 't':
        out += '\t';
        break;
      case 'n':
        out += '\n';
        break;
      case 'r':
        out += '\r';
        break;
      case 'f':
        out += '\f';
        break;
      default:
        appendUtf8(out, static_cast<unsigned char>(e));
    }
  }
  flushHigh();
  return out;
}

std::optional<double> number(const std::map<std::string, std::string>& p, const std::string& key,
                             const fs::path& source) {
  const auto it = p.find(key);
  if (it == p.end() || it->second.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(it->second.c_str(), &end);
  if (end == it->second.c_str() || *end != '\0') {
    throw FileError(source, "'" + key + "' is not a number: '" + it->second + "'");
  }
  return value;
}

}  // namespace

std::map<std::string, std::string> parseJavaProperties(std::string_view bytes,
                                                       const fs::path& source) {
  std::map<std::string, std::string> properties;
  for (const auto& [lineNumber, line] : logicalLines(bytes)) {
    std::size_t keyEnd = 0;
    while (keyEnd < line.size()) {
      const char c = line[keyEnd];
      if (c == '\\') {
        keyEnd += 2;
        continue;
      }
      if (c == '=' || c == ':' || c == ' ' || c == '\t' || c == '\f') break;
      ++keyEnd;
    }
    keyEnd = std::min(keyEnd, line.size());
    std::size_t valueStart = keyEnd;
    while (valueStart < line.size() &&
           (line[valueStart] == ' ' || line[valueStart] == '\t' || line[valueStart] == '\f')) {
      ++valueStart;
    }
    if (valueStart < line.size() && (line[valueStart] == '=' || line[valueStart] == ':')) {
      ++valueStart;
      while (valueStart < line.size() &&
             (line[valueStart] == ' ' || line[valueStart] == '\t' || line[valueStart] == '\f')) {
        ++valueStart;
      }
    }
    properties[unescape(std::string_view(line).substr(0, keyEnd), source, lineNumber)] =
        unescape(std::string_view(line).substr(valueStart), source, lineNumber);
  }
  return properties;
}

FurnitureCatalog parseFurnitureCatalog(std::string_view bytes, const fs::path& source) {
  const auto p = parseJavaProperties(bytes, source);
  auto get = [&](const std::string& key) {
    const auto it = p.find(key);
    return it == p.end() ? std::string() : it->second;
  };
  FurnitureCatalog catalog;
  catalog.id = get("id");
  catalog.name = get("name");
  catalog.license = get("license");
  catalog.version = get("version");
  std::vector<int> indices;
  for (const auto& [key, value] : p) {
    if (key.rfind("id#", 0) != 0) continue;
    const std::string digits = key.substr(3);
    if (digits.empty() || !std::all_of(digits.begin(), digits.end(), [](char c) {
          return std::isdigit(static_cast<unsigned char>(c)) != 0;
        })) {
      continue;
    }
    indices.push_back(std::atoi(digits.c_str()));
  }
  std::sort(indices.begin(), indices.end());
  for (const int index : indices) {
    const std::string n = "#" + std::to_string(index);
    FurnitureCatalogEntry entry;
    entry.index = index;
    entry.id = get("id" + n);
    entry.name = get("name" + n);
    entry.category = get("category" + n);
    entry.creator = get("creator" + n);
    entry.model = get("model" + n);
    if (entry.id.empty() || entry.model.empty()) continue;
    entry.width = number(p, "width" + n, source);
    entry.depth = number(p, "depth" + n, source);
    entry.height = number(p, "height" + n, source);
    const std::string rotation = get("modelRotation" + n);
    if (!rotation.empty()) {
      std::vector<double> values;
      const char* at = rotation.c_str();
      char* end = nullptr;
      for (double v = std::strtod(at, &end); end != at; v = std::strtod(at, &end)) {
        values.push_back(v);
        at = end;
      }
      if (values.size() != 9 || *end != '\0') {
        throw FileError(source, "'modelRotation" + n + "' is not 9 numbers: '" + rotation + "'");
      }
      entry.modelRotation = values;
    }
    catalog.entries.push_back(std::move(entry));
  }
  return catalog;
}

const char* toString(CorpusRole role) {
  switch (role) {
    case CorpusRole::Stove:
      return "stove";
    case CorpusRole::Sink:
      return "sink";
    case CorpusRole::None:
      return "none";
  }
  return "none";
}

std::optional<CorpusRole> selectCorpusRole(const FurnitureCatalogEntry& entry) {
  if (entry.category != "Kitchen" && entry.category != "Bathroom") return std::nullopt;
  static const std::regex stove("cooker|cooktop|stove|hob", std::regex::icase);
  // A tap alone is a sink (issue 41's rule): it has the sink's controls and outlet.
  static const std::regex sink("sink|washbasin|lavatory|basin|vanity|faucet|\\btaps?\\b",
                               std::regex::icase);
  // Small appliances first: a rice cooker or a pressure cooker has no hob.
  static const std::regex appliance("rice cooker|pressure cooker|slow cooker", std::regex::icase);
  static const std::regex distractor(
      "oven|microwave|coffee (machine|maker|brewer)|dishwasher|hood|fridge|refrigerator|"
      "washing machine|clothes washer|toaster|deep fryer|sandwich|grill|kettle|blender|mixer|dryer",
      std::regex::icase);
  const std::string& name = entry.name;
  if (std::regex_search(name, appliance)) return CorpusRole::None;
  if (std::regex_search(name, stove)) return CorpusRole::Stove;
  if (std::regex_search(name, sink)) {
    std::string lower = asciiLower(name);
    for (std::size_t at; (at = lower.find("basin")) != std::string::npos;) lower.erase(at, 5);
    if (lower.find("bath") == std::string::npos && lower.find("shower") == std::string::npos)
      return CorpusRole::Sink;
  }
  if (std::regex_search(name, distractor)) return CorpusRole::None;
  return std::nullopt;
}

std::string corpusObjectId(const std::string& catalogId) {
  std::string id;
  bool gap = false;
  for (const char raw : catalogId) {
    const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(raw)));
    if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) {
      if (gap && !id.empty()) id += '_';
      id += c;
      gap = false;
    } else {
      gap = true;
    }
  }
  if (id.empty()) id = "object";
  if (id.size() > kMaxCorpusIdLength) {
    // Deterministic and still unique in practice: the hash covers the full catalog id.
    const std::string hash = sha256Hex(catalogId).substr(0, 8);
    const std::size_t keep = kMaxCorpusIdLength - hash.size() - 1;
    id = id.substr(0, keep);
    while (!id.empty() && id.back() == '_') id.pop_back();
    id += "_" + hash;
  }
  return id;
}

}  // namespace sagrid
