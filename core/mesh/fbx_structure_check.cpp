#include "core/mesh/fbx_structure_check.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/common/error.h"
#include "core/io/little_endian.h"
#include "core/mesh/mesh_file_check.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {

// What the depth check needs from either encoding: the ids of Model objects and the
// object-to-object connections (child, parent). Ids are kept as text (FBX 6 ASCII names them).
struct FbxGraph {
  std::vector<std::string> models;
  std::vector<std::pair<std::string, std::string>> objectLinks;  // child, parent
};

void refuseDepth(const fs::path& path, const char* what) {
  throw FileError(path, std::string("nests its FBX ") + what + " more than " +
                            std::to_string(kMaxSceneDepth) +
                            " levels deep; SAGrid reads at most that many");
}

// ---- binary FBX: records are (end offset, property count, property bytes, name, properties,
// nested records ending in a null record); offsets are 32-bit before version 7500, 64-bit after.

class BinaryFbxScanner {
 public:
  BinaryFbxScanner(std::string_view b, const fs::path& path) : m_b(b), m_path(path) {}

  FbxGraph scan() {
    constexpr std::size_t kHeader = 27;
    if (m_b.size() < kHeader) fail("binary FBX header is truncated");
    const std::uint32_t version = io::u32(m_b, 23);
    m_wide = version >= 7500;
    FbxGraph graph;
    std::vector<std::uint64_t> ends{m_b.size()};  // end of the enclosing record, outermost first
    std::vector<std::string> names;               // names of the enclosing records
    std::uint64_t at = kHeader;
    while (true) {
      const std::uint64_t headerSize = m_wide ? 25 : 13;
      if (at + headerSize > ends.back()) {
        if (ends.size() == 1) break;  // the top level may end without its null record
        if (at != ends.back()) {
          fail("binary FBX record at byte " + std::to_string(at) + " runs past its parent");
        }
        ends.pop_back();  // a nested list that ends without its null record
        names.pop_back();
        continue;
      }
      const std::uint64_t end = offset(at);
      const std::uint64_t propertyBytes = offset(at + (m_wide ? 16 : 8));
      const std::uint8_t nameLength = static_cast<std::uint8_t>(m_b[at + headerSize - 1]);
      if (end == 0) {  // null record: the end of a nested list (or of the top level)
        if (ends.size() == 1) break;
        at = ends.back();
        ends.pop_back();
        names.pop_back();
        continue;
      }
      const std::uint64_t nameAt = at + headerSize;
      const std::uint64_t propertiesAt = nameAt + nameLength;
      if (end <= at || end > ends.back() || propertiesAt > end ||
          propertyBytes > end - propertiesAt) {
        fail("binary FBX record at byte " + std::to_string(at) +
             " declares an end outside the file or its parent");
      }
      const std::string name(m_b.substr(nameAt, nameLength));
      const std::string_view properties = m_b.substr(propertiesAt, propertyBytes);
      if (names.size() == 1 && names[0] == "Objects" && name == "Model") {
        const auto p = leadingProperties(properties, 1);
        if (!p.empty()) graph.models.push_back(p[0]);
      } else if (names.size() == 1 && names[0] == "Connections" && name == "C") {
        const auto p = leadingProperties(properties, 3);
        if (p.size() == 3 && p[0] == "OO") graph.objectLinks.push_back({p[1], p[2]});
      }
      const std::uint64_t childrenAt = propertiesAt + propertyBytes;
      if (childrenAt < end) {
        if (static_cast<int>(ends.size()) > kMaxSceneDepth) refuseDepth(m_path, "records");
        ends.push_back(end);
        names.push_back(name);
        at = childrenAt;
      } else {
        at = end;
      }
    }
    return graph;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw FileError(m_path, problem); }

  std::uint64_t offset(std::uint64_t at) const {
    return m_wide ? io::u64(m_b, at) : std::uint64_t{io::u32(m_b, at)};
  }

  // The first `count` scalar or string properties as text ("" for the others), stopping at the
  // first one that does not fit.
  std::vector<std::string> leadingProperties(std::string_view p, std::size_t count) const {
    std::vector<std::string> out;
    std::size_t at = 0;
    while (out.size() < count && at < p.size()) {
      const char type = p[at++];
      auto fits = [&](std::size_t n) { return at + n <= p.size(); };
      switch (type) {
        case 'L':
          if (!fits(8)) return out;
          out.push_back(std::to_string(static_cast<std::int64_t>(io::u64(p, at))));
          at += 8;
          break;
        case 'I':
          if (!fits(4)) return out;
          out.push_back(std::to_string(static_cast<std::int32_t>(io::u32(p, at))));
          at += 4;
          break;
        case 'S':
        case 'R': {
          if (!fits(4)) return out;
          const std::uint64_t n = io::u32(p, at);
          at += 4;
          if (!fits(n)) return out;
          out.emplace_back(type == 'S' ? std::string(p.substr(at, n)) : std::string());
          at += n;
          break;
        }
        case 'Y':
        case 'C':
        case 'F':
        case 'D': {
          const std::size_t n = type == 'Y' ? 2 : type == 'C' ? 1 : type == 'F' ? 4 : 8;
          if (!fits(n)) return out;
          out.emplace_back();
          at += n;
          break;
        }
        default:  // arrays and unknown types: not needed for the hierarchy
          return out;
      }
    }
    return out;
  }

  std::string_view m_b;
  const fs::path& m_path;
  bool m_wide = false;
};

// ---- ASCII FBX: `Name: values {` blocks; ';' starts a comment outside strings.

std::vector<std::string> asciiValues(std::string_view text) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < text.size() && text[i] != '{') {
    const char c = text[i];
    if (c == '"') {
      const std::size_t close = text.find('"', i + 1);
      out.emplace_back(
          text.substr(i + 1, (close == std::string_view::npos ? text.size() : close) - i - 1));
      i = close == std::string_view::npos ? text.size() : close + 1;
    } else if (std::isalnum(static_cast<unsigned char>(c)) || c == '-') {
      const std::size_t start = i;
      while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) ||
                                 text[i] == '-' || text[i] == '.' || text[i] == '_'))
        ++i;
      out.emplace_back(text.substr(start, i - start));
    } else {
      ++i;
    }
  }
  return out;
}

FbxGraph scanAsciiFbx(std::string_view b, const fs::path& path) {
  FbxGraph graph;
  std::vector<std::string> blocks;  // names of the enclosing blocks
  for (std::size_t at = 0; at < b.size();) {
    std::size_t next = b.find('\n', at);
    if (next == std::string_view::npos) next = b.size();
    const std::string_view line = b.substr(at, next - at);
    at = next + 1;
    // Braces outside strings and comments open and close blocks.
    std::string key;
    std::size_t colon = std::string_view::npos;
    bool inString = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (c == '"') inString = !inString;
      if (inString) continue;
      if (c == ';') break;
      if (c == ':' && colon == std::string_view::npos) {
        colon = i;
        std::size_t s = 0;
        while (s < i && std::isspace(static_cast<unsigned char>(line[s]))) ++s;
        key = std::string(line.substr(s, i - s));
      } else if (c == '{') {
        if (static_cast<int>(blocks.size()) >= kMaxSceneDepth) refuseDepth(path, "blocks");
        blocks.push_back(key);
      } else if (c == '}' && !blocks.empty()) {
        blocks.pop_back();
      }
    }
    if (colon == std::string_view::npos) continue;
    const bool opened =
        !blocks.empty() && blocks.back() == key && line.find('{') != std::string_view::npos;
    const std::size_t parentLevel = blocks.size() - (opened ? 1 : 0);
    if (parentLevel != 1) continue;
    const std::string& parent = blocks[0];
    const auto values = asciiValues(line.substr(colon + 1));
    if (parent == "Objects" && key == "Model" && !values.empty()) {
      graph.models.push_back(values[0]);
    } else if (parent == "Connections" && (key == "C" || key == "Connect") && values.size() >= 3 &&
               values[0] == "OO") {
      graph.objectLinks.push_back({values[1], values[2]});
    }
  }
  return graph;
}

// ---- the model hierarchy: longest chain and number of root-to-model paths, in topological order

void checkModelHierarchy(const FbxGraph& graph, const fs::path& path) {
  std::unordered_map<std::string, std::size_t> index;
  for (const auto& id : graph.models) index.emplace(id, index.size());
  const std::size_t n = index.size();
  std::vector<std::vector<std::size_t>> children(n);
  std::vector<std::size_t> parents(n, 0);
  for (const auto& [child, parent] : graph.objectLinks) {
    const auto c = index.find(child), p = index.find(parent);
    if (c == index.end() || p == index.end()) continue;  // attached to the root or not a model
    children[p->second].push_back(c->second);
    ++parents[c->second];
  }
  std::vector<int> depth(n, 1);
  std::vector<std::size_t> paths(n, 0), waiting(parents), ready;
  for (std::size_t i = 0; i < n; ++i)
    if (parents[i] == 0) ready.push_back(i), paths[i] = 1;
  std::size_t done = 0;
  while (!ready.empty()) {
    const std::size_t node = ready.back();
    ready.pop_back();
    ++done;
    if (depth[node] > kMaxSceneDepth) refuseDepth(path, "models");
    for (std::size_t c : children[node]) {
      depth[c] = std::max(depth[c], depth[node] + 1);
      paths[c] = std::min(kMaxFbxModelPaths + 1, paths[c] + paths[node]);
      if (paths[c] > kMaxFbxModelPaths) {
        throw FileError(path, "has FBX models with several parents that expand to more than " +
                                  std::to_string(kMaxFbxModelPaths) + " instances");
      }
      if (--waiting[c] == 0) ready.push_back(c);
    }
  }
  if (done < n) throw FileError(path, "has FBX models that are their own ancestors (a cycle)");
}

}  // namespace

void checkFbxStructure(std::string_view bytes, bool binary, const fs::path& path) {
  const FbxGraph graph = binary ? BinaryFbxScanner(bytes, path).scan() : scanAsciiFbx(bytes, path);
  checkModelHierarchy(graph, path);
}

}  // namespace sagrid
