#include "core/mesh/mesh_export.h"

#include <stb_image_write.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <nlohmann/json.hpp>

#include "core/common/ascii_case.h"
#include "core/common/atomic_file.h"
#include "core/common/contained_paths.h"
#include "core/common/error.h"

namespace sagrid {

namespace {

// Locale-independent shortest-ish float text with fixed significant digits.
void appendFloat(std::string& out, float value, int precision) {
  if (value == 0.0f) value = 0.0f;  // no "-0"
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, precision);
  out.append(buffer, result.ptr);
}

void appendInt(std::string& out, long long value) {
  char buffer[24];
  auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

std::string materialName(const Mesh& mesh, int index) {
  if (index >= 0 && index < static_cast<int>(mesh.materials.size()) && !mesh.materials[index].name.empty()) {
    std::string name = mesh.materials[index].name;
    std::replace(name.begin(), name.end(), ' ', '_');
    return name;
  }
  return "material_" + std::to_string(index);
}

// Material names as OBJ/MTL statements may carry them, by material index: a name comes from the
// imported file, so a line break in it would add statements (a `map_Kd /etc/hostname` for the
// next importer to read) and a space would split it. Each becomes a safe file-name-like word
// (safeFileName), unique within the mesh; an unnamed material is "material_<index>".
std::vector<std::string> objMaterialNames(const Mesh& mesh) {
  UniqueFileNames unique;
  std::vector<std::string> names;
  for (std::size_t m = 0; m < mesh.materials.size(); ++m)
    names.push_back(unique.claim(mesh.materials[m].name, "material_" + std::to_string(m)));
  return names;
}

// Triangle indices grouped by material, materials in index order (-1 first when present).
std::vector<std::pair<int, std::vector<int>>> trianglesByMaterial(const Mesh& mesh) {
  std::vector<std::pair<int, std::vector<int>>> groups;
  const int materialCount = static_cast<int>(mesh.materials.size());
  std::vector<std::vector<int>> buckets(materialCount + 1);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    int m = mesh.triangleMaterials.empty() ? -1 : mesh.triangleMaterials[t];
    if (m < 0 || m >= materialCount) m = -1;
    buckets[m + 1].push_back(t);
  }
  for (int m = -1; m < materialCount; ++m) {
    if (!buckets[m + 1].empty()) groups.emplace_back(m, std::move(buckets[m + 1]));
  }
  return groups;
}

void pngWriteCallback(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

std::string encodePng(const Texture& texture) {
  std::string bytes;
  if (texture.width <= 0 || texture.height <= 0) throw Error("cannot encode an empty texture as PNG");
  if (!stbi_write_png_to_func(pngWriteCallback, &bytes, texture.width, texture.height, 4, texture.rgba.data(),
                              texture.width * 4)) {
    throw Error("PNG encoding failed");
  }
  return bytes;
}

EncodedMeshFiles encodeObj(const Mesh& mesh, const std::string& baseName) {
  EncodedMeshFiles out;
  std::string obj;
  obj.reserve(mesh.positions.size() * 90 + mesh.triangles.size() * 40);
  obj += "# written by sagrid\nmtllib " + baseName + ".mtl\n";
  const bool hasColors = mesh.colors.size() == mesh.positions.size() && !mesh.colors.empty();
  const bool hasUvs = mesh.uvs.size() == mesh.positions.size() && !mesh.uvs.empty();
  const bool hasNormals = mesh.normals.size() == mesh.positions.size() && !mesh.normals.empty();
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Eigen::Vector3f p = zUpToFile(mesh.positions[i], mesh.fileUp);
    obj += "v ";
    appendFloat(obj, p.x(), 7);
    obj += ' ';
    appendFloat(obj, p.y(), 7);
    obj += ' ';
    appendFloat(obj, p.z(), 7);
    if (hasColors) {
      for (int k = 0; k < 3; ++k) {
        obj += ' ';
        appendFloat(obj, mesh.colors[i][k], 4);
      }
    }
    obj += '\n';
  }
  if (hasUvs) {
    for (const auto& uv : mesh.uvs) {
      obj += "vt ";
      appendFloat(obj, uv.x(), 6);
      obj += ' ';
      appendFloat(obj, uv.y(), 6);
      obj += '\n';
    }
  }
  if (hasNormals) {
    for (const auto& n0 : mesh.normals) {
      const Eigen::Vector3f n = zUpToFile(n0, mesh.fileUp);
      obj += "vn ";
      appendFloat(obj, n.x(), 4);
      obj += ' ';
      appendFloat(obj, n.y(), 4);
      obj += ' ';
      appendFloat(obj, n.z(), 4);
      obj += '\n';
    }
  }
  const std::vector<std::string> materialNames = objMaterialNames(mesh);
  for (const auto& [material, triangles] : trianglesByMaterial(mesh)) {
    obj += "usemtl " +
           (material >= 0 ? materialNames[std::size_t(material)] : materialName(mesh, material)) +
           "\n";
    for (int t : triangles) {
      obj += 'f';
      for (int k = 0; k < 3; ++k) {
        const long long index = mesh.triangles[t][k] + 1LL;
        obj += ' ';
        appendInt(obj, index);
        if (hasUvs || hasNormals) {
          obj += '/';
          if (hasUvs) appendInt(obj, index);
          if (hasNormals) {
            obj += '/';
            appendInt(obj, index);
          }
        }
      }
      obj += '\n';
    }
  }

  std::string mtl = "# written by sagrid\n";
  std::vector<std::pair<std::string, std::string>> images;
  for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
    const Material& material = mesh.materials[m];
    mtl += "newmtl " + materialNames[m] + "\nKd ";
    for (int k = 0; k < 3; ++k) {
      appendFloat(mtl, material.baseColor[k], 4);
      mtl += k < 2 ? " " : "\n";
    }
    mtl += "Ka 0 0 0\nKs 0.1 0.1 0.1\nd 1\nillum 2\n";
    if (material.texture >= 0 && material.texture < static_cast<int>(mesh.textures.size())) {
      const std::string image = baseName + "_tex" + std::to_string(material.texture) + ".png";
      mtl += "map_Kd " + image + "\n";
      if (std::none_of(images.begin(), images.end(), [&](const auto& i) { return i.first == image; })) {
        images.emplace_back(image, encodePng(mesh.textures[material.texture]));
      }
    }
    mtl += '\n';
  }
  out.files.emplace_back(baseName + ".obj", std::move(obj));
  out.files.emplace_back(baseName + ".mtl", std::move(mtl));
  for (auto& image : images) out.files.push_back(std::move(image));
  return out;
}

std::string encodeGlb(const Mesh& mesh) {
  using nlohmann::json;
  std::string bin;
  json bufferViews = json::array(), accessors = json::array();
  auto align = [&bin]() {
    while (bin.size() % 4 != 0) bin.push_back('\0');
  };
  auto addView = [&](const void* data, std::size_t bytes, int target) {
    align();
    json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
    if (target) view["target"] = target;
    bin.append(static_cast<const char*>(data), bytes);
    bufferViews.push_back(view);
    return static_cast<int>(bufferViews.size()) - 1;
  };
  auto addAccessor = [&](int view, int componentType, std::size_t count, const char* type) {
    accessors.push_back({{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}});
    return static_cast<int>(accessors.size()) - 1;
  };
  constexpr int kFloat = 5126, kUint = 5125, kArrayBuffer = 34962, kElementBuffer = 34963;

  const std::size_t n = mesh.positions.size();
  std::vector<float> positions(n * 3), normals;
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max()), hi = -lo;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f p = zUpToFile(mesh.positions[i], mesh.fileUp);
    for (int k = 0; k < 3; ++k) positions[i * 3 + k] = p[k];
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  json attributes;
  const int positionAccessor = addAccessor(addView(positions.data(), positions.size() * 4, kArrayBuffer), kFloat, n, "VEC3");
  accessors[positionAccessor]["min"] = {lo.x(), lo.y(), lo.z()};
  accessors[positionAccessor]["max"] = {hi.x(), hi.y(), hi.z()};
  attributes["POSITION"] = positionAccessor;
  if (mesh.normals.size() == n && n > 0) {
    normals.resize(n * 3);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3f v = zUpToFile(mesh.normals[i], mesh.fileUp);
      for (int k = 0; k < 3; ++k) normals[i * 3 + k] = v[k];
    }
    attributes["NORMAL"] = addAccessor(addView(normals.data(), normals.size() * 4, kArrayBuffer), kFloat, n, "VEC3");
  }
  if (mesh.uvs.size() == n && n > 0) {
    std::vector<float> uvs(n * 2);
    for (std::size_t i = 0; i < n; ++i) {
      uvs[i * 2] = mesh.uvs[i].x();
      uvs[i * 2 + 1] = 1.0f - mesh.uvs[i].y();  // glTF's UV origin is the top-left corner
    }
    attributes["TEXCOORD_0"] = addAccessor(addView(uvs.data(), uvs.size() * 4, kArrayBuffer), kFloat, n, "VEC2");
  }
  if (mesh.colors.size() == n && n > 0) {
    std::vector<float> colors(n * 3);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) colors[i * 3 + k] = mesh.colors[i][k];
    attributes["COLOR_0"] = addAccessor(addView(colors.data(), colors.size() * 4, kArrayBuffer), kFloat, n, "VEC3");
  }

  json materials = json::array(), textures = json::array(), images = json::array();
  std::vector<int> textureIndexOfImage(mesh.textures.size(), -1);
  for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
    const Material& material = mesh.materials[m];
    json pbr = {{"baseColorFactor", {material.baseColor.x(), material.baseColor.y(), material.baseColor.z(), 1.0}},
                {"metallicFactor", 0.0},
                {"roughnessFactor", 0.7}};
    if (material.texture >= 0 && material.texture < static_cast<int>(mesh.textures.size())) {
      int& textureIndex = textureIndexOfImage[material.texture];
      if (textureIndex < 0) {
        const std::string png = encodePng(mesh.textures[material.texture]);
        const int view = addView(png.data(), png.size(), 0);
        images.push_back({{"bufferView", view}, {"mimeType", "image/png"}});
        textures.push_back({{"source", images.size() - 1}, {"sampler", 0}});
        textureIndex = static_cast<int>(textures.size()) - 1;
      }
      pbr["baseColorTexture"] = {{"index", textureIndex}};
    }
    materials.push_back({{"name", materialName(mesh, static_cast<int>(m))}, {"pbrMetallicRoughness", pbr}, {"doubleSided", true}});
  }

  json primitives = json::array();
  for (const auto& [material, triangles] : trianglesByMaterial(mesh)) {
    std::vector<std::uint32_t> indices;
    indices.reserve(triangles.size() * 3);
    for (int t : triangles)
      for (int k = 0; k < 3; ++k) indices.push_back(static_cast<std::uint32_t>(mesh.triangles[t][k]));
    const int view = addView(indices.data(), indices.size() * 4, kElementBuffer);
    json primitive = {{"attributes", attributes}, {"indices", addAccessor(view, kUint, indices.size(), "SCALAR")}, {"mode", 4}};
    if (material >= 0) primitive["material"] = material;
    primitives.push_back(primitive);
  }
  align();

  json gltf = {{"asset", {{"version", "2.0"}, {"generator", "sagrid"}}},
               {"scene", 0},
               {"scenes", {{{"nodes", {0}}}}},
               {"nodes", {{{"mesh", 0}}}},
               {"meshes", {{{"primitives", primitives}}}},
               {"accessors", accessors},
               {"bufferViews", bufferViews},
               {"buffers", {{{"byteLength", bin.size()}}}}};
  if (!materials.empty()) gltf["materials"] = materials;
  if (!textures.empty()) {
    gltf["textures"] = textures;
    gltf["images"] = images;
    gltf["samplers"] = {{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}};
  }
  std::string jsonText = gltf.dump();
  while (jsonText.size() % 4 != 0) jsonText.push_back(' ');

  std::string glb;
  auto put32 = [&glb](std::uint32_t v) {
    for (int k = 0; k < 4; ++k) glb.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
  };
  const std::uint32_t total = 12 + 8 + static_cast<std::uint32_t>(jsonText.size()) + 8 + static_cast<std::uint32_t>(bin.size());
  put32(0x46546C67);  // "glTF"
  put32(2);
  put32(total);
  put32(static_cast<std::uint32_t>(jsonText.size()));
  put32(0x4E4F534A);  // "JSON"
  glb += jsonText;
  put32(static_cast<std::uint32_t>(bin.size()));
  put32(0x004E4942);  // "BIN\0"
  glb += bin;
  return glb;
}

void writeEncodedMeshFiles(const EncodedMeshFiles& encoded, const std::filesystem::path& dir) {
  for (const auto& [name, bytes] : encoded.files) writeFileAtomic(dir / name, bytes);
}

void exportMesh(const Mesh& mesh, const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".glb") {
    writeFileAtomic(path, encodeGlb(mesh));
  } else if (ext == ".obj") {
    writeEncodedMeshFiles(encodeObj(mesh, path.stem().string()), path.parent_path());
  } else {
    throw FileError(path, "cannot write this mesh format (use .obj or .glb)");
  }
}

}  // namespace sagrid
