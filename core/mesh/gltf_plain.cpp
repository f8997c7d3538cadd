#include "core/mesh/gltf_plain.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <system_error>

#include "core/common/atomic_file.h"
#include "core/common/contained_paths.h"
#include "core/common/data_uri.h"
#include "core/common/error.h"
#include "core/common/joined.h"
#include "core/common/log.h"
#include "core/io/json_file.h"
#include "core/mesh/gltf_asset.h"
#include "core/mesh/gltf_draco.h"
#include "core/mesh/texture_decode.h"

namespace sagrid {
namespace fs = std::filesystem;
using nlohmann::json;

const std::vector<std::string>& rewrittenGltfExtensions() {
  static const std::vector<std::string> names{"KHR_draco_mesh_compression", "EXT_meshopt_compression",
                                              "KHR_mesh_quantization", "EXT_texture_webp",
                                              "KHR_texture_transform"};
  return names;
}

namespace {

constexpr const char* kDraco = "KHR_draco_mesh_compression";
constexpr const char* kTextureTransform = "KHR_texture_transform";

bool isRewritten(const std::string& name) {
  const auto& names = rewrittenGltfExtensions();
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Extensions that only change how a surface looks or is lit: reading the geometry without them
// loses nothing SAGrid uses.
bool isSafelyIgnored(const std::string& name) {
  return name.rfind("KHR_materials_", 0) == 0 || name == "KHR_lights_punctual" ||
         name == "KHR_xmp_json_ld" || name == "KHR_xmp" || name == "EXT_lights_image_based" ||
         name == "KHR_animation_pointer";
}

std::vector<std::string> namesIn(const json& document, const char* key) {
  std::vector<std::string> names;
  const auto it = document.find(key);
  if (it == document.end() || !it->is_array()) return names;
  for (const auto& n : *it)
    if (n.is_string()) names.push_back(n.get<std::string>());
  return names;
}

void requireReadableExtensions(const json& document, const fs::path& path) {
  for (const std::string& name : namesIn(document, "extensionsRequired")) {
    if (isRewritten(name) || isSafelyIgnored(name)) continue;
    throw FileError(path, "requires the glTF extension " + name +
                              ", which SAGrid cannot read (it reads " +
                              joined(rewrittenGltfExtensions()) +
                              " and ignores material and light extensions)");
  }
}

bool hasWebpImage(const json& document) {
  const auto images = document.find("images");
  if (images == document.end() || !images->is_array()) return false;
  for (const auto& image : *images) {
    if (!image.is_object()) continue;
    if (image.value("mimeType", std::string()) == "image/webp") return true;
    const std::string uri = image.value("uri", std::string());
    if (dataUriMediaType(uri) == "image/webp") return true;
    if (uri.size() >= 5 && uri.compare(uri.size() - 5, 5, ".webp") == 0) return true;
  }
  return false;
}

bool needsRewrite(const json& document) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"})
    for (const std::string& name : namesIn(document, key))
      if (isRewritten(name)) return true;
  return hasWebpImage(document);
}

// A 2D affine map of texture coordinates (KHR_texture_transform: translation * rotation * scale).
struct UvTransform {
  Eigen::Matrix<double, 2, 3> matrix = (Eigen::Matrix<double, 2, 3>() << 1, 0, 0, 0, 1, 0).finished();

  static UvTransform of(const json& ext) {
    auto pair = [&](const char* key, double fallback0, double fallback1) {
      const auto it = ext.find(key);
      if (it == ext.end() || !it->is_array() || it->size() != 2 || !(*it)[0].is_number() ||
          !(*it)[1].is_number())
        return Eigen::Vector2d(fallback0, fallback1);
      return Eigen::Vector2d((*it)[0].get<double>(), (*it)[1].get<double>());
    };
    const Eigen::Vector2d offset = pair("offset", 0, 0), scale = pair("scale", 1, 1);
    const auto r = ext.find("rotation");
    const double rotation = r != ext.end() && r->is_number() ? r->get<double>() : 0.0;
    const double c = std::cos(rotation), s = std::sin(rotation);
    UvTransform t;
    t.matrix << c * scale.x(), s * scale.y(), offset.x(), -s * scale.x(), c * scale.y(), offset.y();
    return t;
  }
};

// What a material asks of its primitives' texture coordinates: which set its base colour reads
// and the transform to bake into it.
struct BaseColorUv {
  int set = 0;
  std::optional<UvTransform> transform;
};

BaseColorUv baseColorUvOf(const json& document, const json& primitive) {
  BaseColorUv uv;
  const auto m = primitive.find("material");
  const auto materials = document.find("materials");
  if (m == primitive.end() || !m->is_number_unsigned() || materials == document.end() ||
      !materials->is_array() || m->get<std::size_t>() >= materials->size())
    return uv;
  const json& material = (*materials)[m->get<std::size_t>()];
  if (!material.is_object() || !material.contains("pbrMetallicRoughness")) return uv;
  const json& pbr = material["pbrMetallicRoughness"];
  if (!pbr.is_object() || !pbr.contains("baseColorTexture") || !pbr["baseColorTexture"].is_object()) return uv;
  const json& info = pbr["baseColorTexture"];
  uv.set = info.value("texCoord", 0);
  if (info.contains("extensions") && info["extensions"].is_object() && info["extensions"].contains(kTextureTransform)) {
    const json& ext = info["extensions"][kTextureTransform];
    if (ext.is_object()) {
      uv.transform = UvTransform::of(ext);
      if (ext.contains("texCoord") && ext["texCoord"].is_number_unsigned()) uv.set = ext["texCoord"].get<int>();
    }
  }
  return uv;
}

// The plain GLB under construction: one binary buffer, fresh buffer views and accessors.
class PlainGlbWriter {
 public:
  std::size_t addView(const std::string& bytes) {
    while (m_binary.size() % 4 != 0) m_binary += '\0';
    m_views.push_back(json{{"buffer", 0}, {"byteOffset", m_binary.size()}, {"byteLength", bytes.size()}});
    m_binary += bytes;
    return m_views.size() - 1;
  }

  std::size_t addFloats(const std::vector<double>& values, int components, bool withBounds) {
    static const char* kTypes[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
    std::string bytes(values.size() * 4, '\0');
    for (std::size_t i = 0; i < values.size(); ++i) {
      const float f = static_cast<float>(values[i]);
      std::memcpy(bytes.data() + 4 * i, &f, 4);
    }
    json accessor{{"bufferView", addView(bytes)}, {"componentType", 5126},
                  {"count", values.size() / components}, {"type", kTypes[components]}};
    if (withBounds && !values.empty()) {
      json lo = json::array(), hi = json::array();
      for (int c = 0; c < components; ++c) {
        double a = values[c], b = values[c];
        for (std::size_t i = c; i < values.size(); i += components) a = std::min(a, values[i]), b = std::max(b, values[i]);
        lo.push_back(static_cast<float>(a));
        hi.push_back(static_cast<float>(b));
      }
      accessor["min"] = lo;
      accessor["max"] = hi;
    }
    m_accessors.push_back(std::move(accessor));
    return m_accessors.size() - 1;
  }

  std::size_t addIndices(const std::vector<std::uint32_t>& indices) {
    std::string bytes(indices.size() * 4, '\0');
    std::memcpy(bytes.data(), indices.data(), bytes.size());
    m_accessors.push_back(json{{"bufferView", addView(bytes)}, {"componentType", 5125},
                               {"count", indices.size()}, {"type", "SCALAR"}});
    return m_accessors.size() - 1;
  }

  std::string finish(json document) {
    document["accessors"] = m_accessors;
    document["bufferViews"] = m_views;
    return writeGlb(std::move(document), m_binary);
  }

 private:
  std::string m_binary;
  json m_accessors = json::array();
  json m_views = json::array();
};

bool keepsAttribute(const std::string& name) {
  return name == "POSITION" || name == "NORMAL" || name.rfind("TEXCOORD_", 0) == 0 || name.rfind("COLOR_", 0) == 0;
}

std::size_t accessorIndex(const GltfAsset& asset, const json& value, const std::string& where) {
  if (!value.is_number_unsigned()) throw FileError(asset.path, where + " does not name an accessor");
  return value.get<std::size_t>();
}

std::size_t accessorCount(const GltfAsset& asset, std::size_t accessor) {
  const json& a = gltfElement(asset, "accessors", accessor);
  return a.contains("count") && a["count"].is_number_unsigned() ? a["count"].get<std::size_t>() : 0;
}

// Rewrites one primitive of the output document into plain accessors.
void rewritePrimitive(const GltfAsset& asset, const json& source, json& primitive,
                      const std::string& where, PlainGlbWriter& writer) {
  if (!source.contains("attributes") || !source["attributes"].is_object()) {
    throw FileError(asset.path, where + " has no attributes");
  }
  std::optional<DecodedDracoPrimitive> draco;
  if (source.contains("extensions") && source["extensions"].is_object() && source["extensions"].contains(kDraco)) {
    const json& ext = source["extensions"][kDraco];
    std::map<std::string, int> ids;
    if (ext.contains("attributes") && ext["attributes"].is_object()) {
      for (const auto& [name, id] : ext["attributes"].items())
        if (id.is_number_integer()) ids[name] = id.get<int>();
    }
    if (!ext.contains("bufferView")) throw FileError(asset.path, where + " (" + kDraco + ") has no bufferView");
    try {
      draco = decodeDracoPrimitive(bufferViewBytes(asset, accessorIndex(asset, ext["bufferView"], where + " (" + kDraco + ")")), ids);
    } catch (const InvalidArgument& e) {
      throw FileError(asset.path, where + " (" + kDraco + "): " + e.what());
    }
  }
  const BaseColorUv uv = baseColorUvOf(asset.document, source);
  json attributes = json::object();
  std::size_t vertices = 0;
  bool first = true;
  for (const auto& [name, value] : source["attributes"].items()) {
    const bool baseUv = name == "TEXCOORD_" + std::to_string(uv.set);
    if (!keepsAttribute(name) || (name.rfind("TEXCOORD_", 0) == 0 && !baseUv)) continue;
    const std::size_t accessor = accessorIndex(asset, value, where + " attribute " + name);
    std::vector<double> values;
    int components = 0;
    if (draco && draco->attributes.count(name)) {
      if (accessorCount(asset, accessor) != draco->points) {
        throw FileError(asset.path, where + " (" + kDraco + "): accessor " + std::to_string(accessor) + " of " + name +
                                        " declares " + std::to_string(accessorCount(asset, accessor)) +
                                        " values but the Draco data decodes " + std::to_string(draco->points));
      }
      components = draco->attributes[name].components;
      values = std::move(draco->attributes[name].values);
    } else {
      AccessorValues read = readAccessor(asset, accessor);
      components = read.components;
      values = std::move(read.values);
    }
    if (components < 1 || components > 4) throw FileError(asset.path, where + " attribute " + name + " is not a vector");
    for (const double v : values) {
      if (!std::isfinite(v)) throw FileError(asset.path, where + " attribute " + name + " holds NaN or infinite values");
    }
    const std::size_t count = values.size() / components;
    if (!first && count != vertices) {
      throw FileError(asset.path, where + " attribute " + name + " has " + std::to_string(count) +
                                      " values where the others have " + std::to_string(vertices));
    }
    first = false;
    vertices = count;
    std::string outName = name;
    if (baseUv) {
      outName = "TEXCOORD_0";
      if (components != 2) throw FileError(asset.path, where + " attribute " + name + " is not VEC2");
      if (uv.transform) {
        for (std::size_t i = 0; i < count; ++i) {
          const Eigen::Vector2d t = uv.transform->matrix * Eigen::Vector3d(values[2 * i], values[2 * i + 1], 1.0);
          values[2 * i] = t.x();
          values[2 * i + 1] = t.y();
        }
      }
    }
    attributes[outName] = writer.addFloats(values, components, name == "POSITION");
  }
  if (!attributes.contains("POSITION")) throw FileError(asset.path, where + " has no POSITION attribute");
  primitive["attributes"] = attributes;
  std::vector<std::uint32_t> indices;
  bool indexed = false;
  if (draco) {
    if (source.contains("indices") &&
        accessorCount(asset, accessorIndex(asset, source["indices"], where + " indices")) != draco->indices.size()) {
      throw FileError(asset.path, where + " (" + kDraco + "): its indices accessor declares " +
                                      std::to_string(accessorCount(asset, source["indices"].get<std::size_t>())) +
                                      " indices but the Draco data decodes " + std::to_string(draco->indices.size()));
    }
    indices = std::move(draco->indices);
    indexed = true;
  } else if (source.contains("indices")) {
    const AccessorValues read = readAccessor(asset, accessorIndex(asset, source["indices"], where + " indices"));
    indices.reserve(read.values.size());
    for (const double v : read.values) indices.push_back(static_cast<std::uint32_t>(v));
    indexed = true;
  }
  for (const std::uint32_t i : indices) {
    if (i >= vertices) {
      throw FileError(asset.path, where + " has index " + std::to_string(i) + " beyond its " +
                                      std::to_string(vertices) + " vertices");
    }
  }
  if (indexed) primitive["indices"] = writer.addIndices(indices);
  else primitive.erase("indices");
  primitive.erase("targets");
  if (primitive.contains("extensions") && primitive["extensions"].is_object()) primitive["extensions"].erase(kDraco);
}

// The bytes of image `index` and its media type, or nullopt for an external file that is missing
// (assimp then reports the texture missing, as for any file).
std::optional<std::pair<std::string, std::string>> imageBytes(const GltfAsset& asset, const json& image, std::size_t index) {
  const std::string where = "glTF image " + std::to_string(index);
  std::string bytes;
  if (image.contains("bufferView")) {
    bytes = bufferViewBytes(asset, accessorIndex(asset, image["bufferView"], where));
  } else if (image.contains("uri") && image["uri"].is_string()) {
    const std::string uri = image["uri"].get<std::string>();
    auto read = referencedBytes(asset, uri, where);
    if (!read) {
      logger()->warn("{}: {}: its file '{}' is missing; using the material colour", asset.path.string(), where, uri);
      return std::nullopt;
    }
    bytes = std::move(*read);
  } else {
    return std::nullopt;
  }
  std::string mime = imageMimeType(bytes);
  if (mime.empty()) mime = image.value("mimeType", std::string("image/png"));
  if (mime == "image/webp" && !decodeTexture(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size())) {
    throw FileError(asset.path, where + " is a WebP image that does not decode (corrupt or truncated)");
  }
  return std::make_pair(std::move(bytes), mime);
}

void embedImages(const GltfAsset& asset, json& document, PlainGlbWriter& writer) {
  if (!document.contains("images") || !document["images"].is_array()) return;
  json& images = document["images"];
  for (std::size_t i = 0; i < images.size(); ++i) {
    if (!images[i].is_object()) throw FileError(asset.path, "glTF image " + std::to_string(i) + " is not an object");
    const auto image = imageBytes(asset, images[i], i);
    if (!image) continue;
    json plain{{"bufferView", writer.addView(image->first)}, {"mimeType", image->second}};
    if (images[i].contains("name")) plain["name"] = images[i]["name"];
    images[i] = std::move(plain);
  }
  if (!document.contains("textures") || !document["textures"].is_array()) return;
  for (json& texture : document["textures"]) {
    if (!texture.is_object() || !texture.contains("extensions") || !texture["extensions"].is_object()) continue;
    const json& ext = texture["extensions"];
    if (ext.contains("EXT_texture_webp") && ext["EXT_texture_webp"].contains("source")) {
      texture["source"] = ext["EXT_texture_webp"]["source"];
    }
    texture.erase("extensions");
  }
}

// Texture transforms of the base colour were baked into TEXCOORD_0; that texture now reads set 0.
void dropBakedTransforms(json& document) {
  if (!document.contains("materials") || !document["materials"].is_array()) return;
  for (json& material : document["materials"]) {
    if (!material.is_object() || !material.contains("pbrMetallicRoughness")) continue;
    json& pbr = material["pbrMetallicRoughness"];
    if (!pbr.is_object() || !pbr.contains("baseColorTexture") || !pbr["baseColorTexture"].is_object()) continue;
    json& info = pbr["baseColorTexture"];
    info["texCoord"] = 0;
    if (info.contains("extensions") && info["extensions"].is_object()) info["extensions"].erase(kTextureTransform);
  }
}

void dropRewrittenNames(json& document) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    if (!document.contains(key)) continue;
    json kept = json::array();
    for (const std::string& name : namesIn(document, key))
      if (!isRewritten(name)) kept.push_back(name);
    document[key] = kept;
  }
}

}  // namespace

std::optional<std::string> plainGlbOf(std::string_view bytes, const fs::path& path) {
  {
    // Extensions first, from the JSON alone: a plain file's buffers are assimp's to read.
    const json document = readGltfDocument(bytes, path);
    requireReadableExtensions(document, path);
    if (!needsRewrite(document)) return std::nullopt;
  }
  const GltfAsset asset = readGltfAsset(bytes, path);
  json document = asset.document;
  PlainGlbWriter writer;
  if (document.contains("meshes") && document["meshes"].is_array()) {
    for (std::size_t m = 0; m < document["meshes"].size(); ++m) {
      json& mesh = document["meshes"][m];
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) {
        throw FileError(path, "glTF mesh " + std::to_string(m) + " has no primitives");
      }
      for (std::size_t p = 0; p < mesh["primitives"].size(); ++p) {
        const std::string where = "glTF mesh " + std::to_string(m) + " primitive " + std::to_string(p);
        const json& source = asset.document["meshes"][m]["primitives"][p];
        if (!source.is_object()) throw FileError(path, where + " is not an object");
        rewritePrimitive(asset, source, mesh["primitives"][p], where, writer);
      }
    }
  }
  embedImages(asset, document, writer);
  dropBakedTransforms(document);
  dropRewrittenNames(document);
  document.erase("animations");
  document.erase("skins");
  if (document.contains("nodes") && document["nodes"].is_array()) {
    for (json& node : document["nodes"])
      if (node.is_object()) node.erase("skin");
  }
  if (document.contains("extensions") && document["extensions"].is_object()) document["extensions"].erase("EXT_meshopt_compression");
  return writer.finish(std::move(document));
}

}  // namespace sagrid
