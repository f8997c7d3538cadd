#include "core/mesh/gltf_asset.h"

#include <meshoptimizer.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <system_error>

#include "core/common/atomic_file.h"
#include "core/common/contained_paths.h"
#include "core/common/data_uri.h"
#include "core/common/error.h"
#include "core/io/json_file.h"

namespace sagrid {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67u;  // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534Au;
constexpr std::uint32_t kBinChunk = 0x004E4942u;

std::uint32_t u32At(std::string_view b, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

// What one buffer view may decode to and one accessor may hold: far beyond any appliance mesh,
// short of what a hostile count would make us allocate.
constexpr std::size_t kMaxDecodedViewBytes = std::size_t{1} << 29;  // 512 MiB
constexpr std::size_t kMaxAccessorValues = std::size_t{1} << 26;    // 512 MiB of doubles

[[noreturn]] void fail(const GltfAsset& asset, const std::string& problem) {
  throw FileError(asset.path, problem);
}

// A non-negative integer field of a glTF object, or `fallback` when absent.
std::size_t sizeField(const GltfAsset& asset, const json& object, const char* key,
                      const std::string& where, std::size_t fallback = 0) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number_unsigned() && !(it->is_number_integer() && it->get<std::int64_t>() >= 0)) {
    fail(asset, where + " has a '" + key + "' that is not a non-negative integer");
  }
  const std::uint64_t value = it->get<std::uint64_t>();
  if (value > std::numeric_limits<std::uint32_t>::max() * std::uint64_t{16}) {
    fail(asset, where + " has an implausible '" + key + "' (" + std::to_string(value) + ")");
  }
  return static_cast<std::size_t>(value);
}

std::size_t requiredSize(const GltfAsset& asset, const json& object, const char* key,
                         const std::string& where) {
  if (!object.contains(key)) fail(asset, where + " has no '" + key + "'");
  return sizeField(asset, object, key, where);
}

std::string bufferBytes(GltfAsset& asset, const json& buffer, std::size_t index,
                        const std::string* glbBinary) {
  const std::string where = "glTF buffer " + std::to_string(index);
  const std::size_t declared = sizeField(asset, buffer, "byteLength", where);
  std::string bytes;
  const auto uri = buffer.find("uri");
  if (uri != buffer.end()) {
    if (!uri->is_string()) fail(asset, where + " has a 'uri' that is not text");
    const std::string text = uri->get<std::string>();
    auto read = referencedBytes(asset, text, where);
    if (!read) fail(asset, where + ": its file '" + text + "' is missing");
    bytes = std::move(*read);
  } else if (index == 0 && glbBinary) {
    bytes = *glbBinary;
  } else if (buffer.contains("extensions") && buffer["extensions"].contains("EXT_meshopt_compression")) {
    return {};  // a fallback buffer: its views are all compressed elsewhere
  } else {
    fail(asset, where + " has no data: no 'uri' and it is not the GLB's binary chunk");
  }
  if (bytes.size() < declared) {
    fail(asset, where + " declares " + std::to_string(declared) + " bytes but holds " +
                    std::to_string(bytes.size()) + " (truncated?)");
  }
  bytes.resize(declared);
  return bytes;
}

// The decoded bytes of an EXT_meshopt_compression buffer view (count * byteStride).
std::string decodeMeshoptView(const GltfAsset& asset, const json& ext, const std::string& where) {
  const std::string ctx = where + " (EXT_meshopt_compression)";
  const std::size_t buffer = requiredSize(asset, ext, "buffer", ctx);
  if (buffer >= asset.buffers.size()) fail(asset, ctx + " names buffer " + std::to_string(buffer) + ", which does not exist");
  const std::size_t offset = sizeField(asset, ext, "byteOffset", ctx);
  const std::size_t length = requiredSize(asset, ext, "byteLength", ctx);
  const std::size_t stride = requiredSize(asset, ext, "byteStride", ctx);
  const std::size_t count = requiredSize(asset, ext, "count", ctx);
  const std::string& source = asset.buffers[buffer];
  if (offset > source.size() || length > source.size() - offset) {
    fail(asset, ctx + " lies outside buffer " + std::to_string(buffer) + " (truncated?)");
  }
  if (stride == 0 || stride > 256 || count > kMaxDecodedViewBytes / stride) {
    fail(asset, ctx + " has an implausible byteStride " + std::to_string(stride) + " or count " + std::to_string(count));
  }
  const std::string mode = ext.value("mode", std::string("ATTRIBUTES"));
  const std::string filter = ext.value("filter", std::string("NONE"));
  std::string out(count * stride, '\0');
  const auto* src = reinterpret_cast<const unsigned char*>(source.data() + offset);
  int result = -1;
  if (mode == "ATTRIBUTES") {
    if (stride % 4 != 0) fail(asset, ctx + ": attribute stride " + std::to_string(stride) + " is not a multiple of 4");
    result = meshopt_decodeVertexBuffer(out.data(), count, stride, src, length);
  } else if (mode == "TRIANGLES" || mode == "INDICES") {
    if (stride != 2 && stride != 4) fail(asset, ctx + ": index stride must be 2 or 4");
    if (mode == "TRIANGLES" && count % 3 != 0) fail(asset, ctx + ": TRIANGLES count is not a multiple of 3");
    result = mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out.data(), count, stride, src, length)
                                 : meshopt_decodeIndexSequence(out.data(), count, stride, src, length);
  } else {
    fail(asset, ctx + " has unknown mode '" + mode + "'");
  }
  if (result != 0) fail(asset, ctx + " does not decode (corrupt or truncated data)");
  if (filter == "OCTAHEDRAL") {
    if (stride != 4 && stride != 8) fail(asset, ctx + ": OCTAHEDRAL filter needs stride 4 or 8");
    meshopt_decodeFilterOct(out.data(), count, stride);
  } else if (filter == "QUATERNION") {
    if (stride != 8) fail(asset, ctx + ": QUATERNION filter needs stride 8");
    meshopt_decodeFilterQuat(out.data(), count, stride);
  } else if (filter == "EXPONENTIAL") {
    meshopt_decodeFilterExp(out.data(), count, stride);
  } else if (filter != "NONE") {
    fail(asset, ctx + " has unknown filter '" + filter + "'");
  }
  return out;
}

std::size_t componentSize(int componentType) {
  switch (componentType) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 0;
  }
}

double componentValue(const char* at, int componentType, bool normalized) {
  switch (componentType) {
    case 5120: { std::int8_t v; std::memcpy(&v, at, 1); return normalized ? std::max(v / 127.0, -1.0) : v; }
    case 5121: { std::uint8_t v; std::memcpy(&v, at, 1); return normalized ? v / 255.0 : v; }
    case 5122: { std::int16_t v; std::memcpy(&v, at, 2); return normalized ? std::max(v / 32767.0, -1.0) : v; }
    case 5123: { std::uint16_t v; std::memcpy(&v, at, 2); return normalized ? v / 65535.0 : v; }
    case 5125: { std::uint32_t v; std::memcpy(&v, at, 4); return v; }
    default: { float v; std::memcpy(&v, at, 4); return v; }
  }
}

// Fails unless `count` elements of `elementSize` bytes at `offset` with `stride` lie in `bytes`
// (checked before anything is allocated for them).
void requireElementsFit(const GltfAsset& asset, const std::string& bytes, std::size_t offset, std::size_t stride,
                        std::size_t count, std::size_t elementSize, const std::string& where) {
  if (count == 0) return;
  if (offset > bytes.size() || (count - 1) > (bytes.size() - offset) / std::max<std::size_t>(stride, 1) ||
      offset + (count - 1) * stride + elementSize > bytes.size()) {
    fail(asset, where + " reads past the end of its buffer view (" + std::to_string(count) +
                    " elements of " + std::to_string(elementSize) + " bytes from byte " +
                    std::to_string(offset) + " of " + std::to_string(bytes.size()) + ")");
  }
}

// Reads `count` elements of `components` values each from `bytes` at `offset` with `stride`.
void readElements(const GltfAsset& asset, const std::string& bytes, std::size_t offset,
                  std::size_t stride, std::size_t count, int components, int componentType,
                  bool normalized, const std::string& where, double* out) {
  const std::size_t elementSize = componentSize(componentType) * static_cast<std::size_t>(components);
  requireElementsFit(asset, bytes, offset, stride, count, elementSize, where);
  const std::size_t size = componentSize(componentType);
  for (std::size_t e = 0; e < count; ++e) {
    const char* element = bytes.data() + offset + e * stride;
    for (int c = 0; c < components; ++c) {
      out[e * components + c] = componentValue(element + c * size, componentType, normalized);
    }
  }
}

}  // namespace

std::optional<std::string> referencedBytes(const GltfAsset& asset, const std::string& uri, const std::string& where) {
  try {
    if (auto inline_ = dataUriBytes(uri)) return inline_;
  } catch (const InvalidArgument& e) {
    fail(asset, where + ": " + e.what());
  }
  const fs::path folder = asset.path.parent_path().empty() ? fs::path(".") : asset.path.parent_path();
  const fs::path file = resolveContained(folder, percentDecoded(uri), asset.path);
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  return readFileBytes(file);
}

const json& gltfElement(const GltfAsset& asset, const char* array, std::size_t index) {
  const auto it = asset.document.find(array);
  if (it == asset.document.end() || !it->is_array() || index >= it->size() || !(*it)[index].is_object()) {
    fail(asset, std::string("glTF ") + array + "[" + std::to_string(index) + "] does not exist or is malformed");
  }
  return (*it)[index];
}

int accessorComponents(std::string_view type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

namespace {
// The JSON of a .glb or .gltf, and for a GLB its BIN chunk (nullopt when it has none).
std::pair<json, std::optional<std::string_view>> gltfParts(std::string_view bytes, const fs::path& path) {
  if (bytes.size() < 12 || u32At(bytes, 0) != kGlbMagic) return {parseJsonDocument(bytes, path), std::nullopt};
  const std::size_t declared = std::min<std::size_t>(u32At(bytes, 8), bytes.size());
  const std::size_t jsonLength = u32At(bytes, 12);
  if (u32At(bytes, 16) != kJsonChunk || 20 + jsonLength > declared)
    throw FileError(path, "binary glTF has no valid JSON chunk");
  json document = parseJsonDocument(bytes.substr(20, jsonLength), path);
  const std::size_t binAt = 20 + ((jsonLength + 3) & ~std::size_t{3});
  if (binAt + 8 > declared || u32At(bytes, binAt + 4) != kBinChunk) return {std::move(document), std::nullopt};
  const std::size_t length = u32At(bytes, binAt);
  if (binAt + 8 + length > declared) throw FileError(path, "binary glTF's BIN chunk is truncated");
  return {std::move(document), bytes.substr(binAt + 8, length)};
}
}  // namespace

json readGltfDocument(std::string_view bytes, const fs::path& path) {
  json document = gltfParts(bytes, path).first;
  if (!document.is_object()) throw FileError(path, "glTF JSON is not an object");
  return document;
}

GltfAsset readGltfAsset(std::string_view bytes, const fs::path& path) {
  GltfAsset asset;
  asset.path = path;
  auto [document, bin] = gltfParts(bytes, path);
  asset.document = std::move(document);
  const std::string binary = bin ? std::string(*bin) : std::string();
  const bool hasBinary = bin.has_value();
  if (!asset.document.is_object()) fail(asset, "glTF JSON is not an object");
  const auto buffers = asset.document.find("buffers");
  if (buffers != asset.document.end()) {
    if (!buffers->is_array()) fail(asset, "glTF 'buffers' is not an array");
    for (std::size_t b = 0; b < buffers->size(); ++b) {
      if (!(*buffers)[b].is_object()) fail(asset, "glTF buffer " + std::to_string(b) + " is not an object");
      asset.buffers.push_back(bufferBytes(asset, (*buffers)[b], b, hasBinary ? &binary : nullptr));
    }
  }
  return asset;
}

std::string bufferViewBytes(const GltfAsset& asset, std::size_t view) {
  const json& v = gltfElement(asset, "bufferViews", view);
  const std::string where = "glTF buffer view " + std::to_string(view);
  if (v.contains("extensions") && v["extensions"].is_object() &&
      v["extensions"].contains("EXT_meshopt_compression")) {
    return decodeMeshoptView(asset, v["extensions"]["EXT_meshopt_compression"], where);
  }
  const std::size_t buffer = requiredSize(asset, v, "buffer", where);
  if (buffer >= asset.buffers.size()) fail(asset, where + " names buffer " + std::to_string(buffer) + ", which does not exist");
  const std::size_t offset = sizeField(asset, v, "byteOffset", where);
  const std::size_t length = requiredSize(asset, v, "byteLength", where);
  const std::string& source = asset.buffers[buffer];
  if (offset > source.size() || length > source.size() - offset) {
    fail(asset, where + " lies outside buffer " + std::to_string(buffer) + " (bytes " + std::to_string(offset) +
                    "+" + std::to_string(length) + " of " + std::to_string(source.size()) + "; truncated?)");
  }
  return source.substr(offset, length);
}

AccessorValues readAccessor(const GltfAsset& asset, std::size_t index) {
  const json& a = gltfElement(asset, "accessors", index);
  const std::string where = "glTF accessor " + std::to_string(index);
  AccessorValues result;
  result.count = requiredSize(asset, a, "count", where);
  result.components = accessorComponents(a.value("type", std::string()));
  const int componentType = static_cast<int>(requiredSize(asset, a, "componentType", where));
  if (result.components == 0) fail(asset, where + " has an unknown type");
  if (componentSize(componentType) == 0) fail(asset, where + " has unknown componentType " + std::to_string(componentType));
  if (result.count > kMaxAccessorValues / static_cast<std::size_t>(result.components))
    fail(asset, where + " declares an implausible count " + std::to_string(result.count));
  const bool normalized = a.value("normalized", false);
  const std::size_t elementSize = componentSize(componentType) * static_cast<std::size_t>(result.components);
  if (a.contains("bufferView")) {
    const std::size_t view = sizeField(asset, a, "bufferView", where);
    const std::string bytes = bufferViewBytes(asset, view);
    const json& v = gltfElement(asset, "bufferViews", view);
    std::size_t stride = sizeField(asset, v, "byteStride", where, 0);
    if (v.contains("extensions") && v["extensions"].contains("EXT_meshopt_compression")) {
      stride = sizeField(asset, v["extensions"]["EXT_meshopt_compression"], "byteStride", where, 0);
    }
    if (stride == 0) stride = elementSize;
    const std::size_t offset = sizeField(asset, a, "byteOffset", where);
    requireElementsFit(asset, bytes, offset, stride, result.count, elementSize, where);
    result.values.assign(result.count * result.components, 0.0);
    readElements(asset, bytes, offset, stride, result.count, result.components, componentType, normalized, where,
                 result.values.data());
  } else {
    result.values.assign(result.count * result.components, 0.0);
  }
  if (a.contains("sparse")) {
    const json& sparse = a["sparse"];
    const std::string sw = where + " (sparse)";
    const std::size_t count = requiredSize(asset, sparse, "count", sw);
    if (count > result.count) fail(asset, sw + " substitutes more elements than the accessor has");
    if (!sparse.contains("indices") || !sparse.contains("values")) fail(asset, sw + " lacks indices or values");
    const json& si = sparse["indices"];
    const json& sv = sparse["values"];
    const int indexType = static_cast<int>(requiredSize(asset, si, "componentType", sw));
    if (indexType != 5121 && indexType != 5123 && indexType != 5125) fail(asset, sw + " has an index type that is not unsigned");
    std::vector<double> indices(count);
    readElements(asset, bufferViewBytes(asset, requiredSize(asset, si, "bufferView", sw)),
                 sizeField(asset, si, "byteOffset", sw), componentSize(indexType), count, 1, indexType,
                 false, sw, indices.data());
    std::vector<double> values(count * result.components);
    readElements(asset, bufferViewBytes(asset, requiredSize(asset, sv, "bufferView", sw)),
                 sizeField(asset, sv, "byteOffset", sw), elementSize, count, result.components,
                 componentType, normalized, sw, values.data());
    for (std::size_t s = 0; s < count; ++s) {
      const auto target = static_cast<std::size_t>(indices[s]);
      if (target >= result.count) fail(asset, sw + " substitutes element " + std::to_string(target) + " of " + std::to_string(result.count));
      std::copy_n(values.begin() + s * result.components, result.components,
                  result.values.begin() + target * result.components);
    }
  }
  return result;
}

std::string writeGlb(json document, const std::string& binary) {
  document["buffers"] = json::array({json{{"byteLength", binary.size()}}});
  std::string text = document.dump();
  while (text.size() % 4 != 0) text += ' ';
  std::string bin = binary;
  while (bin.size() % 4 != 0) bin += '\0';
  auto put = [](std::string& out, std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  std::string out;
  put(out, kGlbMagic);
  put(out, 2);
  put(out, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
  put(out, static_cast<std::uint32_t>(text.size()));
  put(out, kJsonChunk);
  out += text;
  put(out, static_cast<std::uint32_t>(bin.size()));
  put(out, kBinChunk);
  out += bin;
  return out;
}

}  // namespace sagrid
