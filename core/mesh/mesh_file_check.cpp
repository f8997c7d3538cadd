#include "core/mesh/mesh_file_check.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "core/common/error.h"
#include "core/io/json_file.h"
#include "core/io/little_endian.h"
#include "core/mesh/fbx_structure_check.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {

using io::u32;

bool startsWith(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

std::string_view trimmedStart(std::string_view text) {
  std::size_t i = 0;
  if (startsWith(text, "\xEF\xBB\xBF")) i = 3;  // UTF-8 byte order mark
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  return text.substr(i);
}

bool isBinaryStl(std::string_view b) {
  return b.size() >= 84 && 84 + 50 * std::uint64_t{u32(b, 80)} == b.size();
}

bool looksLikeObj(std::string_view b) {
  const std::string_view head = b.substr(0, 4096);
  if (head.find('\0') != std::string_view::npos) return false;
  for (std::size_t at = 0; at < head.size();) {
    const std::string_view line = trimmedStart(head.substr(at, head.find('\n', at) - at));
    for (std::string_view keyword : {"v ", "vn ", "vt ", "f ", "o ", "g ", "mtllib ", "usemtl "}) {
      if (startsWith(line, keyword)) return true;
    }
    const std::size_t next = head.find('\n', at);
    if (next == std::string_view::npos) break;
    at = next + 1;
  }
  return false;
}

// ---- glTF: node hierarchy depth, without recursion

void checkGltfNodes(const nlohmann::json& gltf, const fs::path& path) {
  const auto nodesIt = gltf.find("nodes");
  if (nodesIt == gltf.end() || !nodesIt->is_array()) return;
  const nlohmann::json& nodes = *nodesIt;
  const std::size_t n = nodes.size();
  std::vector<std::vector<std::size_t>> children(n);
  std::vector<int> parents(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto it = nodes[i].is_object() ? nodes[i].find("children") : nodes[i].end();
    if (!nodes[i].is_object() || it == nodes[i].end()) continue;
    if (!it->is_array()) throw FileError(path, "glTF node " + std::to_string(i) + " has malformed children");
    for (const auto& c : *it) {
      if (!c.is_number_unsigned() || c.get<std::uint64_t>() >= n) {
        throw FileError(path, "glTF node " + std::to_string(i) + " lists a child that does not exist");
      }
      const auto child = static_cast<std::size_t>(c.get<std::uint64_t>());
      if (++parents[child] > 1) {
        throw FileError(path, "glTF node " + std::to_string(child) +
                                  " has more than one parent (the glTF spec allows one)");
      }
      children[i].push_back(child);
    }
  }
  std::vector<bool> seen(n, false);
  std::vector<std::pair<std::size_t, int>> stack;
  for (std::size_t root = 0; root < n; ++root) {
    if (parents[root] != 0) continue;
    stack.push_back({root, 1});
    while (!stack.empty()) {
      const auto [node, depth] = stack.back();
      stack.pop_back();
      seen[node] = true;
      if (depth > kMaxSceneDepth) {
        throw FileError(path, "nests its glTF nodes more than " + std::to_string(kMaxSceneDepth) +
                                  " levels deep; SAGrid reads at most that many");
      }
      for (std::size_t c : children[node]) stack.push_back({c, depth + 1});
    }
  }
  // With one parent each, what no root reaches lies on a cycle.
  if (std::find(seen.begin(), seen.end(), false) != seen.end()) {
    throw FileError(path, "has glTF nodes that are their own ancestors (a cycle)");
  }
}

void checkGlb(std::string_view b, const fs::path& path) {
  if (b.size() < 20) throw FileError(path, "binary glTF is truncated (" + std::to_string(b.size()) + " bytes)");
  const std::uint32_t version = u32(b, 4), declared = u32(b, 8);
  if (version != 2) {
    throw FileError(path, "binary glTF version " + std::to_string(version) +
                              " is not supported (glTF 2.0 only)");
  }
  if (declared > b.size()) {
    throw FileError(path, "binary glTF header declares " + std::to_string(declared) +
                              " bytes but the file has " + std::to_string(b.size()) +
                              " (truncated?)");
  }
  const std::uint64_t jsonLength = u32(b, 12);
  if (u32(b, 16) != 0x4E4F534Au) throw FileError(path, "binary glTF does not start with its JSON chunk");
  if (20 + jsonLength > declared) {
    throw FileError(path, "binary glTF JSON chunk declares " + std::to_string(jsonLength) +
                              " bytes, more than the file holds");
  }
  for (std::uint64_t at = 20 + ((jsonLength + 3) & ~std::uint64_t{3}); at + 8 <= declared;) {
    const std::uint64_t length = u32(b, at);
    if (at + 8 + length > declared) {
      throw FileError(path, "binary glTF chunk at byte " + std::to_string(at) + " declares " +
                                std::to_string(length) + " bytes, more than the file holds");
    }
    at += 8 + ((length + 3) & ~std::uint64_t{3});
  }
  checkGltfNodes(parseJsonDocument(b.substr(20, jsonLength), path), path);
}

// ---- COLLADA: element nesting (assimp's XML reader and node walk recurse)

void checkXmlDepth(std::string_view b, const fs::path& path) {
  int depth = 0;
  for (std::size_t at = b.find('<'); at != std::string_view::npos; at = b.find('<', at)) {
    auto skipTo = [&](std::string_view end) {
      const std::size_t found = b.find(end, at);
      at = found == std::string_view::npos ? b.size() : found + end.size();
    };
    const std::string_view rest = b.substr(at);
    if (startsWith(rest, "<!--")) { skipTo("-->"); continue; }
    if (startsWith(rest, "<![CDATA[")) { skipTo("]]>"); continue; }
    if (startsWith(rest, "<?") || startsWith(rest, "<!")) { skipTo(">"); continue; }
    const bool closing = startsWith(rest, "</");
    char quote = 0;
    std::size_t end = at + 1;
    for (; end < b.size(); ++end) {
      if (quote) {
        if (b[end] == quote) quote = 0;
      } else if (b[end] == '"' || b[end] == '\'') {
        quote = b[end];
      } else if (b[end] == '>') {
        break;
      }
    }
    const bool selfClosing = end < b.size() && b[end - 1] == '/';
    if (closing) --depth;
    else if (!selfClosing && ++depth > kMaxSceneDepth) {
      throw FileError(path, "nests its XML elements more than " + std::to_string(kMaxSceneDepth) +
                                " levels deep; SAGrid reads at most that many");
    }
    at = end;
  }
}

// ---- PLY: the header's promises against the data

struct PlyProperty {
  int size = 0;       // bytes of a scalar, or of each list item
  int countSize = 0;  // bytes of a list's count; 0 for a scalar
  bool signedItems = false;
};

bool plyTypeSigned(const std::string& type) {
  return type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" ||
         type == "int32";
}

// assimp asserts in its triangulation on faces of fewer than 3 vertices and reads out of bounds
// on indices past the vertex list; both are refused here.
constexpr std::uint64_t kMaxFaceVertices = 4096;
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

int plyTypeSize(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

// Calls `word(start, length)` for each whitespace-separated word of `line`.
template <typename Word>
void forEachWord(std::string_view line, Word word) {
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) word(start, i - start);
  }
}

std::vector<std::string> words(std::string_view line) {
  std::vector<std::string> out;
  forEachWord(line, [&](std::size_t start, std::size_t length) {
    out.emplace_back(line.substr(start, length));
  });
  return out;
}

// words(line).size() without making the words (an OBJ has a face line per triangle).
std::size_t wordCount(std::string_view line) {
  std::size_t count = 0;
  forEachWord(line, [&count](std::size_t, std::size_t) { ++count; });
  return count;
}

class PlyCheck {
 public:
  PlyCheck(std::string_view bytes, const fs::path& path) : m_b(bytes), m_path(path) {}

  MeshFileFacts run() {
    readHeader();
    MeshFileFacts facts;
    facts.declaredTriangles = m_format == "ascii" ? checkAscii() : checkBinary();
    return facts;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw FileError(m_path, "PLY " + problem); }

  void readHeader() {
    // end_header on a line of its own (a fuzzed "...end_headerent face" made assimp crash).
    std::size_t end = std::string_view::npos;
    for (std::size_t at = m_b.find("\nend_header"); at != std::string_view::npos && at < (1u << 20);
         at = m_b.find("\nend_header", at + 1)) {
      const std::size_t after = at + 11;
      if (after < m_b.size() && (m_b[after] == '\n' || m_b[after] == '\r')) {
        end = at + 1;
        break;
      }
    }
    if (end == std::string_view::npos) fail("header has no end_header line (the file is truncated?)");
    std::size_t dataStart = m_b.find('\n', end);
    if (dataStart == std::string_view::npos) fail("header is not followed by data (the file is truncated?)");
    m_dataStart = dataStart + 1;
    const std::string_view header = m_b.substr(0, end);
    int lineNumber = 0;
    for (std::size_t at = 0; at < header.size();) {
      std::size_t next = header.find('\n', at);
      if (next == std::string_view::npos) next = header.size();
      const std::string_view lineText = header.substr(at, next - at);
      const auto w = words(lineText);
      at = next + 1;
      ++lineNumber;
      if (lineText.find('\0') != std::string_view::npos)
        fail("header line " + std::to_string(lineNumber) + " holds a NUL byte");
      if (w.empty() || w[0] == "comment" || w[0] == "obj_info" || w[0] == "ply") continue;
      if (w[0] == "format" && w.size() >= 2) {
        m_format = w[1];
        if (m_format != "ascii" && m_format != "binary_little_endian" && m_format != "binary_big_endian")
          fail("format '" + m_format + "' is not ascii or binary");
      } else if (w[0] == "element" && w.size() == 3) {
        PlyElement e;
        e.name = w[1];
        if (w[2].empty() || w[2].size() > 12 || !std::all_of(w[2].begin(), w[2].end(), ::isdigit))
          fail("element '" + e.name + "' has a malformed count '" + w[2] + "'");
        e.count = std::stoull(w[2]);
        // Every instance takes at least a byte, so no count can exceed the file's size.
        if (e.count > m_b.size()) {
          fail("declares " + w[2] + " " + e.name + " elements but the file has only " +
               std::to_string(m_b.size()) + " bytes");
        }
        m_elements.push_back(e);
      } else if (w[0] == "property" && !m_elements.empty()) {
        PlyProperty p;
        if (w.size() == 5 && w[1] == "list") {
          p.countSize = plyTypeSize(w[2]);
          p.size = plyTypeSize(w[3]);
          p.signedItems = plyTypeSigned(w[3]);
          if (!p.countSize || !p.size) fail("list property '" + w[4] + "' has an unknown type");
        } else if (w.size() == 3) {
          p.size = plyTypeSize(w[1]);
          if (!p.size) fail("property '" + w[2] + "' has unknown type '" + w[1] + "'");
        } else {
          fail("header has a malformed property line");
        }
        m_elements.back().properties.push_back(p);
      } else {
        fail("header line " + std::to_string(lineNumber) + " is not a PLY statement");
      }
    }
    if (m_format.empty()) fail("header has no format line");
    for (const PlyElement& e : m_elements)
      if (e.name == "vertex") m_vertexCount = e.count;
  }

  // Every element instance is one line holding exactly its values.
  std::size_t checkAscii() const {
    std::uint64_t declared = 0;
    for (const PlyElement& e : m_elements) declared += e.count;
    const std::string_view data = m_b.substr(m_dataStart);
    // ASCII data is text: a NUL or another control byte (fuzzing found NULs inside face lines
    // that reached an assert in assimp's triangulation) makes the file corrupt, not a mesh.
    const auto control = std::find_if(data.begin(), data.end(), [](char c) {
      const auto u = static_cast<unsigned char>(c);
      return (u < 0x20 && c != '\n' && c != '\r' && c != '\t') || u == 0x7f;
    });
    if (control != data.end()) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", static_cast<unsigned char>(*control));
      fail(std::string("ASCII data holds the control byte ") + hex + " at offset " +
           std::to_string(m_dataStart + static_cast<std::size_t>(control - data.begin())) +
           " (corrupt file)");
    }
    const std::uint64_t lines = std::count(data.begin(), data.end(), '\n') + 1;
    if (declared > lines) {
      fail("declares " + std::to_string(declared) + " elements, one line each, but has only " +
           std::to_string(lines) + " lines of data (truncated?)");
    }
    std::size_t at = m_dataStart, triangles = 0, line = 0;
    for (const PlyElement& e : m_elements) {
      for (std::uint64_t i = 0; i < e.count; ++i) {
        std::vector<std::string> values;
        while (values.empty()) {
          if (at >= m_b.size()) {
            fail("declares " + std::to_string(e.count) + " " + e.name + " elements but the file ends after " +
                 std::to_string(i) + " of them (truncated?)");
          }
          std::size_t next = m_b.find('\n', at);
          if (next == std::string_view::npos) next = m_b.size();
          values = words(m_b.substr(at, next - at));
          at = next + 1;
          ++line;
        }
        std::size_t used = 0;
        for (const PlyProperty& p : e.properties) {
          if (!p.countSize) {
            ++used;
            continue;
          }
          const std::size_t n = used < values.size() ? std::strtoull(values[used].c_str(), nullptr, 10) : 0;
          if (e.name == "face") {
            checkFaceSize(i, n);
            for (std::size_t k = used + 1; k < used + 1 + n && k < values.size(); ++k) {
              const long long index = std::strtoll(values[k].c_str(), nullptr, 10);
              if (index < 0 || static_cast<std::uint64_t>(index) >= m_vertexCount) checkIndex(i, index);
            }
            triangles += n - 2;
          }
          used += 1 + n;
        }
        for (const std::string& v : values) {
          char* end = nullptr;
          std::strtod(v.c_str(), &end);
          if (end != v.c_str() + v.size())
            fail(e.name + " " + std::to_string(i) + " (data line " + std::to_string(line) +
                 ") holds '" + v.substr(0, 16) + "', not a number (corrupt file)");
        }
        if (used != values.size()) {
          fail(e.name + " " + std::to_string(i) + " (data line " + std::to_string(line) + ") has " +
               std::to_string(values.size()) + " values where " + std::to_string(used) +
               " are declared (truncated or corrupt file)");
        }
      }
    }
    return triangles;
  }

  std::size_t checkBinary() const {
    std::uint64_t at = m_dataStart;
    std::size_t triangles = 0;
    auto readCount = [&](int size) -> std::uint64_t { return readValue(at, size); };
    for (const PlyElement& e : m_elements) {
      std::uint64_t fixed = 0;
      bool lists = false;
      for (const PlyProperty& p : e.properties) {
        lists |= p.countSize != 0;
        fixed += p.countSize ? p.countSize : p.size;
      }
      // Enough bytes for every instance's fixed part, before walking the lists one by one.
      if (e.count > 0 && (m_b.size() - std::min<std::uint64_t>(at, m_b.size())) / e.count < fixed) {
        fail("declares " + std::to_string(e.count) + " " + e.name + " elements (" +
             std::to_string(fixed) + "+ bytes each) but the file has " + std::to_string(m_b.size()) +
             " bytes (truncated?)");
      }
      if (!lists) {
        at += fixed * e.count;
        continue;
      }
      for (std::uint64_t i = 0; i < e.count; ++i) {
        for (const PlyProperty& p : e.properties) {
          if (at + (p.countSize ? p.countSize : p.size) > m_b.size()) {
            fail("ends inside " + e.name + " " + std::to_string(i) + " of " + std::to_string(e.count) +
                 " (truncated?)");
          }
          if (!p.countSize) {
            at += p.size;
            continue;
          }
          const std::uint64_t n = readCount(p.countSize);
          if (e.name == "face") {
            checkFaceSize(i, n);
            if (at + p.countSize + n * p.size > m_b.size()) fail("ends inside face " + std::to_string(i) + " (truncated?)");
            for (std::uint64_t k = 0; k < n; ++k) {
              const std::uint64_t raw = readValue(at + p.countSize + k * p.size, p.size);
              const int bits = 8 * p.size;
              const long long index = p.signedItems && bits < 64 && (raw >> (bits - 1)) & 1
                                          ? static_cast<long long>(raw) - (1LL << bits)
                                          : static_cast<long long>(raw);
              if (index < 0 || static_cast<std::uint64_t>(index) >= m_vertexCount) checkIndex(i, index);
            }
            triangles += n - 2;
          }
          at += p.countSize + n * p.size;
        }
      }
      if (at > m_b.size()) fail("ends inside its " + e.name + " elements (truncated?)");
    }
    if (at > m_b.size()) fail("data is shorter than its header declares (truncated?)");
    return triangles;
  }

  std::uint64_t readValue(std::uint64_t at, int size) const {
    const bool little = m_format == "binary_little_endian";
    std::uint64_t v = 0;
    for (int k = 0; k < size; ++k) {
      const auto byte = static_cast<unsigned char>(m_b[at + k]);
      v |= std::uint64_t{byte} << (8 * (little ? k : size - 1 - k));
    }
    return v;
  }

  void checkFaceSize(std::uint64_t face, std::uint64_t n) const {
    if (n < 3 || n > kMaxFaceVertices)
      fail("face " + std::to_string(face) + " lists " + std::to_string(n) +
           " vertices (3.." + std::to_string(kMaxFaceVertices) + " expected; corrupt file?)");
  }

  [[noreturn]] void checkIndex(std::uint64_t face, long long index) const {
    fail("face " + std::to_string(face) + " refers to vertex " + std::to_string(index) + " of " +
         std::to_string(m_vertexCount) + " (corrupt file?)");
  }

  std::string_view m_b;
  fs::path m_path;
  std::uint64_t m_vertexCount = 0;
  std::string m_format;
  std::vector<PlyElement> m_elements;
  std::size_t m_dataStart = 0;
};

// ---- OBJ: how many triangles the faces declare, and whether the last line was cut

MeshFileFacts checkObj(std::string_view b) {
  MeshFileFacts facts;
  std::size_t triangles = 0;
  std::string_view last;
  for (std::size_t at = 0; at < b.size();) {
    std::size_t next = b.find('\n', at);
    if (next == std::string_view::npos) next = b.size();
    const std::string_view line = trimmedStart(b.substr(at, next - at));
    if (!line.empty()) last = line;
    if (line.size() > 2 && line[0] == 'f' && std::isspace(static_cast<unsigned char>(line[1]))) {
      const std::size_t refs = wordCount(line) - 1;
      if (refs >= 3) triangles += refs - 2;
    }
    at = next + 1;
  }
  facts.declaredTriangles = triangles;
  // Programs end every line with a newline; a data line without one was cut mid-statement.
  if (!b.empty() && b.back() != '\n' && !last.empty() && last[0] != '#') {
    facts.truncation = "ends in the middle of a line";
  }
  return facts;
}

void checkBinaryStlSize(std::string_view b, const fs::path& path) {
  if (b.size() < 84) throw FileError(path, "binary STL is truncated (" + std::to_string(b.size()) + " bytes)");
  const std::uint64_t triangles = u32(b, 80), needed = 84 + 50 * triangles;
  if (needed > b.size()) {
    throw FileError(path, "binary STL declares " + std::to_string(triangles) + " triangles (" +
                              std::to_string(needed) + " bytes) but the file has " +
                              std::to_string(b.size()) + " bytes (truncated?)");
  }
}

std::string suggestedExtension(const std::string& format) {
  if (format == "OBJ text") return ".obj";
  if (format == "binary glTF (GLB)") return ".glb";
  if (format == "glTF JSON") return ".gltf";
  if (format == "PLY") return ".ply";
  if (format == "COLLADA XML") return ".dae";
  if (format == "binary FBX" || format == "ASCII FBX") return ".fbx";
  if (format == "binary STL" || format == "ASCII STL") return ".stl";
  return "";
}

}  // namespace

std::string sniffMeshFormat(std::string_view b) {
  if (startsWith(b, "glTF")) return "binary glTF (GLB)";
  if (startsWith(b, "ply\n") || startsWith(b, "ply\r\n")) return "PLY";
  if (startsWith(b, "PK\x03\x04")) return "a zip archive";
  if (startsWith(b, "Kaydara FBX Binary")) return "binary FBX";
  if (isBinaryStl(b)) return "binary STL";
  const std::string_view text = trimmedStart(b);
  if (startsWith(text, "; FBX")) return "ASCII FBX";
  if (startsWith(text, "{")) return "glTF JSON";
  if (startsWith(text, "<") && b.substr(0, 4096).find("<COLLADA") != std::string_view::npos)
    return "COLLADA XML";
  if (startsWith(text, "solid") && b.substr(0, 4096).find("facet") != std::string_view::npos)
    return "ASCII STL";
  if (looksLikeObj(b)) return "OBJ text";
  return "";
}

MeshFileFacts checkMeshFile(std::string_view bytes, const std::string& extension, const fs::path& path) {
  const std::string format = sniffMeshFormat(bytes);
  const std::string expected = extension == ".gltf" && format == "binary glTF (GLB)" ? ".gltf"
                                                                                     : suggestedExtension(format);
  if (!expected.empty() && expected != extension) {
    throw FileError(path, "holds " + format + " but is named " + extension + "; rename it to " +
                              expected);
  }
  if (extension == ".glb" && format.empty()) {
    throw FileError(path, "is not a binary glTF file (no 'glTF' header)");
  }
  if (extension == ".ply" && format.empty()) throw FileError(path, "is not a PLY file (no 'ply' header)");
  if (format == "binary glTF (GLB)") checkGlb(bytes, path);
  if (format == "glTF JSON") checkGltfNodes(parseJsonDocument(bytes, path), path);
  if (format == "COLLADA XML" || extension == ".dae") checkXmlDepth(bytes, path);
  if (format == "binary FBX" || format == "ASCII FBX") checkFbxStructure(bytes, format == "binary FBX", path);
  if (format == "PLY") return PlyCheck(bytes, path).run();
  if (extension == ".stl" && format != "ASCII STL") checkBinaryStlSize(bytes, path);
  if (extension == ".obj") return checkObj(bytes);
  return {};
}

}  // namespace sagrid
