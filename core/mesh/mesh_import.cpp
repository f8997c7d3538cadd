#include "core/mesh/mesh_import.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <future>
#include <map>
#include <set>
#include <system_error>

#include "core/common/ascii_case.h"
#include "core/common/atomic_file.h"
#include "core/common/contained_paths.h"
#include "core/common/error.h"
#include "core/common/log.h"
#include "core/common/sha256.h"
#include "core/common/value_ranges.h"
#include "core/mesh/bounds_check.h"
#include "core/mesh/gltf_plain.h"
#include "core/mesh/import_time_limit.h"
#include "core/mesh/mesh_file_check.h"
#include "core/mesh/object_folder.h"
#include "core/mesh/texture_decode.h"
#include "core/mesh/up_axis_detection.h"

namespace sagrid {
namespace fs = std::filesystem;

const std::vector<std::string>& supportedMeshExtensions() {
  static const std::vector<std::string> extensions{".obj", ".gltf", ".glb", ".fbx",
                                                   ".dae", ".ply", ".stl"};
  return extensions;
}

bool isMeshFile(const fs::path& path) {
  const auto& extensions = supportedMeshExtensions();
  return std::find(extensions.begin(), extensions.end(), lowerExtension(path)) != extensions.end();
}

std::optional<UpAxis> parseUpAxis(const std::string& text) {
  std::string t = asciiLower(text);
  if (!t.empty() && t[0] == '+') t.erase(0, 1);
  if (t == "x") return UpAxis::PosX;
  if (t == "-x") return UpAxis::NegX;
  if (t == "y") return UpAxis::PosY;
  if (t == "-y") return UpAxis::NegY;
  if (t == "z") return UpAxis::PosZ;
  if (t == "-z") return UpAxis::NegZ;
  return std::nullopt;
}

const char* toString(UpAxis up) {
  switch (up) {
    case UpAxis::PosX: return "x";
    case UpAxis::NegX: return "-x";
    case UpAxis::PosY: return "y";
    case UpAxis::NegY: return "-y";
    case UpAxis::NegZ: return "-z";
    case UpAxis::PosZ:
    default: return "z";
  }
}

UpAxis upAxisOrZ(const std::string& text) { return parseUpAxis(text).value_or(UpAxis::Z); }

UpAxis unsureUpAxis(const std::string& extension) {
  return extension == ".obj" ? UpAxis::PosY : UpAxis::PosZ;
}

namespace {

// Assimp's message as one short line of printable ASCII: its parse errors can quote the rest of
// the file (an ASCII STL error carried 45 KB of it, bytes of any value). Linear in the length.
constexpr std::size_t kMaxReasonLength = 300;

std::string oneLine(const std::string& text) {
  std::string out;
  bool pendingSpace = false;
  for (const unsigned char c : text) {
    if (std::isspace(c)) {
      pendingSpace = !out.empty();
      continue;
    }
    if (pendingSpace) out += ' ';
    pendingSpace = false;
    out += c < 0x20 || c >= 0x7f ? '?' : static_cast<char>(c);
    if (out.size() >= kMaxReasonLength) {
      out += "...";
      break;
    }
  }
  return out;
}

// Collects materials and their textures, external (beside the mesh) or embedded in the file.
class MaterialReader {
 public:
  MaterialReader(const aiScene& scene, const fs::path& meshPath, Mesh& mesh)
      : m_scene(scene), m_meshPath(meshPath), m_mesh(mesh) {}

  void readAll() {
    for (unsigned m = 0; m < m_scene.mNumMaterials; ++m) m_mesh.materials.push_back(read(*m_scene.mMaterials[m]));
  }

 private:
  Material read(const aiMaterial& source) {
    Material material;
    aiString name;
    if (source.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) material.name = name.C_Str();
    aiColor4D color;
    if (source.Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS ||
        source.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS) {
      material.baseColor = Eigen::Vector3f(color.r, color.g, color.b).cwiseMax(0.0f).cwiseMin(1.0f);
    }
    for (aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
      aiString texturePath;
      if (source.GetTextureCount(type) > 0 && source.GetTexture(type, 0, &texturePath) == AI_SUCCESS) {
        material.texture = textureIndex(texturePath.C_Str());
        if (material.texture >= 0) break;
      }
    }
    return material;
  }

  int textureIndex(const std::string& reference) {
    if (auto it = m_loaded.find(reference); it != m_loaded.end()) return it->second;
    std::optional<Texture> texture;
    if (const aiTexture* embedded = m_scene.GetEmbeddedTexture(reference.c_str())) {
      texture = decodeEmbedded(*embedded);
    } else {
      texture = loadExternal(reference);
    }
    int index = -1;
    if (texture) {
      index = static_cast<int>(m_mesh.textures.size());
      m_mesh.textures.push_back(std::move(*texture));
    } else {
      logger()->warn("{}: texture '{}' could not be loaded; using the material colour",
                     m_meshPath.string(), reference);
    }
    m_loaded[reference] = index;
    return index;
  }

  static std::optional<Texture> decodeEmbedded(const aiTexture& embedded) {
    if (embedded.mHeight == 0) {  // compressed (PNG, JPEG) bytes, mWidth of them
      return decodeTexture(reinterpret_cast<const unsigned char*>(embedded.pcData), embedded.mWidth);
    }
    Texture texture;  // raw BGRA texels
    texture.width = static_cast<int>(embedded.mWidth);
    texture.height = static_cast<int>(embedded.mHeight);
    texture.rgba.resize(static_cast<std::size_t>(texture.width) * texture.height * 4);
    for (std::size_t i = 0; i < static_cast<std::size_t>(texture.width) * texture.height; ++i) {
      const aiTexel& t = embedded.pcData[i];
      texture.rgba[4 * i + 0] = t.r;
      texture.rgba[4 * i + 1] = t.g;
      texture.rgba[4 * i + 2] = t.b;
      texture.rgba[4 * i + 3] = t.a;
    }
    return texture;
  }

  // As written, then just the file name beside the mesh (exports often carry absolute paths);
  // either way only inside the mesh's own folder, and only regular files. A relative reference
  // into a sibling folder ("../materials/textures/x.png") is read when it stays inside the
  // object's folder (object_folder.h).
  std::optional<Texture> loadExternal(std::string reference) {
    std::replace(reference.begin(), reference.end(), '\\', '/');
    const fs::path dir = m_meshPath.parent_path().empty() ? fs::path(".") : m_meshPath.parent_path();
    if (auto texture = loadFromObjectFolder(dir, reference)) return texture;
    for (const std::string& candidate : {reference, fs::path(reference).filename().string()}) {
      try {
        const fs::path file = resolveContained(dir, candidate, m_meshPath);
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) continue;
        const std::string bytes = readFileBytes(file);
        if (auto texture = decodeTexture(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size())) {
          return texture;
        }
      } catch (const FileError& e) {
        logger()->warn("{}", e.what());
      }
    }
    return std::nullopt;
  }

  std::optional<Texture> loadFromObjectFolder(const fs::path& dir, const std::string& reference) const {
    if (reference.find("..") == std::string::npos || fs::path(reference).is_absolute()) return std::nullopt;
    const fs::path object = objectFolderOf(m_meshPath);
    if (object == dir) return std::nullopt;
    const fs::path file = (dir / reference).lexically_normal();
    std::error_code ec;
    if (!isInsideFolder(file, object) || !fs::is_regular_file(file, ec)) return std::nullopt;
    const std::string bytes = readFileBytes(file);
    return decodeTexture(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
  }

  const aiScene& m_scene;
  fs::path m_meshPath;
  Mesh& m_mesh;
  std::map<std::string, int> m_loaded;
};

// Appends every triangle mesh of the node tree with the accumulated node transform applied.
class GeometryMerger {
 public:
  GeometryMerger(const aiScene& scene, Mesh& mesh) : m_scene(scene), m_mesh(mesh) {}

  void merge() {
    bool anyColors = false, anyUvs = false;
    for (unsigned m = 0; m < m_scene.mNumMeshes; ++m) {
      anyColors |= m_scene.mMeshes[m]->HasVertexColors(0);
      anyUvs |= m_scene.mMeshes[m]->HasTextureCoords(0);
    }
    m_withColors = anyColors;
    m_withUvs = anyUvs;
    visit(*m_scene.mRootNode, aiMatrix4x4());
  }

  const std::vector<bool>& missingNormals() const { return m_missingNormals; }

 private:
  // Depth-first in the file's order, with an explicit stack: node depth is not bounded for
  // every format before assimp reads it.
  void visit(const aiNode& root, const aiMatrix4x4& rootParent) {
    std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack{{&root, rootParent}};
    while (!stack.empty()) {
      const auto [node, parent] = stack.back();
      stack.pop_back();
      const aiMatrix4x4 transform = parent * node->mTransformation;
      aiMatrix3x3 normalMatrix(transform);
      normalMatrix.Inverse().Transpose();
      for (unsigned i = 0; i < node->mNumMeshes; ++i) {
        append(*m_scene.mMeshes[node->mMeshes[i]], transform, normalMatrix);
      }
      for (unsigned c = node->mNumChildren; c-- > 0;) stack.push_back({node->mChildren[c], transform});
    }
  }

  void append(const aiMesh& source, const aiMatrix4x4& transform, const aiMatrix3x3& normalMatrix) {
    if (!(source.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) return;  // points and lines
    const int base = static_cast<int>(m_mesh.positions.size());
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
      const aiVector3D p = transform * source.mVertices[v];
      m_mesh.positions.emplace_back(p.x, p.y, p.z);
      if (source.HasNormals()) {
        aiVector3D n = normalMatrix * source.mNormals[v];
        n.NormalizeSafe();
        m_mesh.normals.emplace_back(n.x, n.y, n.z);
      } else {
        m_mesh.normals.emplace_back(Eigen::Vector3f::Zero());
      }
      m_missingNormals.push_back(!source.HasNormals());
      if (m_withUvs) {
        m_mesh.uvs.push_back(source.HasTextureCoords(0)
                                 ? Eigen::Vector2f(source.mTextureCoords[0][v].x, source.mTextureCoords[0][v].y)
                                 : Eigen::Vector2f::Zero());
      }
      if (m_withColors) {
        m_mesh.colors.push_back(source.HasVertexColors(0)
                                    ? Eigen::Vector3f(source.mColors[0][v].r, source.mColors[0][v].g,
                                                      source.mColors[0][v].b)
                                    : Eigen::Vector3f::Ones());
      }
    }
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
      const aiFace& face = source.mFaces[f];
      if (face.mNumIndices != 3) continue;
      m_mesh.triangles.emplace_back(base + static_cast<int>(face.mIndices[0]),
                                    base + static_cast<int>(face.mIndices[1]),
                                    base + static_cast<int>(face.mIndices[2]));
      m_mesh.triangleMaterials.push_back(static_cast<int>(source.mMaterialIndex));
    }
  }

  const aiScene& m_scene;
  Mesh& m_mesh;
  bool m_withColors = false, m_withUvs = false;
  std::vector<bool> m_missingNormals;
};

// Assimp's file access for one import: the mesh itself comes from the bytes already read (so
// the bytes hashed are the bytes parsed), and the files it references (MTL, .bin buffers) only
// from regular files inside the mesh's own folder; anything else is refused with a warning.
class ContainedIOSystem : public Assimp::DefaultIOSystem {
 public:
  ContainedIOSystem(const fs::path& meshPath, const std::string& bytes)
      : m_meshPath(meshPath),
        m_folder(meshPath.parent_path().empty() ? fs::path(".") : meshPath.parent_path()),
        m_bytes(bytes) {}

  bool Exists(const char* file) const override { return isMesh(file) || allowed(file, false); }

  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (std::string(mode).find_first_of("wa+") != std::string::npos) return nullptr;
    if (isMesh(file)) {
      return new Assimp::MemoryIOStream(reinterpret_cast<const uint8_t*>(m_bytes.data()),
                                        m_bytes.size());
    }
    return allowed(file, true) ? DefaultIOSystem::Open(file, mode) : nullptr;
  }

 private:
  bool isMesh(const char* file) const {
    std::error_code ec;
    return fs::path(file) == m_meshPath || fs::equivalent(file, m_meshPath, ec);
  }

  bool allowed(const char* file, bool warn) const {
    std::error_code ec;
    const bool inside = isInsideFolder(file, m_folder);
    if (inside && fs::is_regular_file(file, ec)) return true;
    if (warn && (!inside || fs::exists(file, ec)) && m_warned.insert(file).second) {
      logger()->warn("{}: not reading '{}': {}", m_meshPath.string(), file,
                     inside ? "not a regular file" : "it lies outside the mesh's folder");
    }
    return false;
  }

  fs::path m_meshPath;
  fs::path m_folder;
  const std::string& m_bytes;
  mutable std::set<std::string> m_warned;
};

UpAxis defaultUpAxis(const std::string& extension, const aiScene& scene) {
  if (extension == ".gltf" || extension == ".glb") return UpAxis::Y;  // by the glTF spec
  if (extension == ".fbx" && scene.mMetaData) {
    int axis = 2;  // FBX GlobalSettings: 0 = x, 1 = y, 2 = z
    if (scene.mMetaData->Get("UpAxis", axis) && axis == 1) return UpAxis::Y;
  }
  return UpAxis::Z;
}

// Drops triangles with repeated indices or zero area; they carry no surface.
std::size_t removeDegenerateTriangles(Mesh& mesh) {
  std::size_t kept = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3f n = (mesh.positions[tri[1]] - mesh.positions[tri[0]])
                                  .cross(mesh.positions[tri[2]] - mesh.positions[tri[0]]);
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] || !(n.squaredNorm() > 0)) continue;
    mesh.triangles[kept] = tri;
    if (!mesh.triangleMaterials.empty()) mesh.triangleMaterials[kept] = mesh.triangleMaterials[t];
    ++kept;
  }
  const std::size_t removed = mesh.triangles.size() - kept;
  mesh.triangles.resize(kept);
  if (!mesh.triangleMaterials.empty()) mesh.triangleMaterials.resize(kept);
  return removed;
}

// A truncated OBJ or PLY that assimp still reads yields fewer triangles than its faces declare,
// or ends mid-statement: an error, or with --lenient a warning saying how much was read.
void reportPartialRead(const fs::path& path, const MeshFileFacts& facts, std::size_t triangles,
                       bool lenient) {
  std::string problem = facts.truncation.empty() ? "" : "it " + facts.truncation;
  if (facts.declaredTriangles && triangles < *facts.declaredTriangles) {
    problem += (problem.empty() ? "only " : "; only ") + std::to_string(triangles) + " of the " +
               std::to_string(*facts.declaredTriangles) + " triangles its faces declare could be read";
  }
  if (problem.empty()) return;
  if (!lenient) throw FileError(path, "is incomplete: " + problem + "; --lenient uses what was read");
  logger()->warn("{}: incomplete file (--lenient): {}; read {} triangles", path.string(), problem,
                 triangles);
}

void fillMissingNormals(Mesh& mesh, const std::vector<bool>& missing) {
  if (std::none_of(missing.begin(), missing.end(), [](bool b) { return b; })) return;
  const std::vector<Eigen::Vector3f> fromFile = mesh.normals;
  mesh.computeVertexNormals();
  for (std::size_t v = 0; v < missing.size(); ++v) {
    if (!missing[v]) mesh.normals[v] = fromFile[v];
  }
}

// Triangles the scene's faces make (n - 2 per face of n >= 3 vertices), as parsed.
std::size_t parsedTriangles(const aiScene& scene) {
  std::size_t triangles = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh* mesh = scene.mMeshes[m];
    if (!mesh || !mesh->mFaces) continue;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices >= 3) triangles += mesh->mFaces[f].mNumIndices - 2;
  }
  return triangles;
}

// Sets each mesh's primitive-type flags from its faces (1 index: point, 2: line, 3: triangle,
// more: polygon), keeping assimp's other flag bits. The scene is the importer's, before any
// post-processing.
void recomputePrimitiveTypes(const aiScene& scene) {
  constexpr unsigned kTypes = aiPrimitiveType_POINT | aiPrimitiveType_LINE |
                              aiPrimitiveType_TRIANGLE | aiPrimitiveType_POLYGON;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    aiMesh* mesh = scene.mMeshes[m];
    if (!mesh || !mesh->mFaces) continue;
    unsigned types = 0;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const unsigned n = mesh->mFaces[f].mNumIndices;
      types |= n == 1   ? aiPrimitiveType_POINT
               : n == 2 ? aiPrimitiveType_LINE
               : n == 3 ? aiPrimitiveType_TRIANGLE
               : n > 3  ? aiPrimitiveType_POLYGON
                        : 0u;
    }
    if (types) mesh->mPrimitiveTypes = (mesh->mPrimitiveTypes & ~kTypes) | types;
  }
}

}  // namespace

namespace {
bool g_lenientByDefault = false;
}

void setLenientImportByDefault(bool lenient) { g_lenientByDefault = lenient; }
bool lenientImportByDefault() { return g_lenientByDefault; }

Mesh importMesh(const fs::path& path, const ImportOptions& options) {
  requireRegularFile(path);  // missing, a folder, a FIFO or a device: say so before anything
  const std::string extension = lowerExtension(path);
  const auto& supported = supportedMeshExtensions();
  if (std::find(supported.begin(), supported.end(), extension) == supported.end()) {
    std::string list;
    for (const auto& e : supported) list += (list.empty() ? "" : " ") + e;
    throw FileError(path, "unsupported mesh format '" + extension + "' (supported: " + list + ")");
  }
  const std::string bytes = readFileBytes(path);
  if (bytes.empty()) throw FileError(path, "is empty (0 bytes)");
  // The file's hash on another core while it is parsed (a tenth of the import of a large OBJ).
  std::future<std::string> sha256 =
      std::async(std::launch::async, [&bytes] { return sha256Hex(bytes); });
  const MeshFileFacts facts = checkMeshFile(bytes, extension, path);
  if (!facts.truncation.empty() && !options.lenient) {
    throw FileError(path, "is incomplete: it " + facts.truncation +
                              " (truncated?); --lenient reads what is there");
  }

  // With --lenient, a statement cut mid-line is left out: assimp would turn "f 1 2" into a line
  // primitive and refuse the whole file.
  std::string parsed = facts.truncation.empty() || bytes.rfind('\n') == std::string::npos
                           ? bytes
                           : bytes.substr(0, bytes.rfind('\n') + 1);
  // A glTF that uses compression, quantization or WebP is handed to assimp as the plain GLB it
  // decodes to, under a name of its own beside the file (gltf_plain.h).
  fs::path parsedPath = path;
  if (extension == ".gltf" || extension == ".glb") {
    if (auto plain = plainGlbOf(bytes, path)) {
      parsed = std::move(*plain);
      parsedPath = path.parent_path() / (path.stem().string() + ".sagrid-plain.glb");
    }
  }
  const ImportDeadline deadline(path, importTimeLimit());
  Assimp::Importer importer;
  importer.SetIOHandler(new ContainedIOSystem(parsedPath, parsed));  // the importer owns it
  if (auto* progress = deadline.newProgressHandler()) importer.SetProgressHandler(progress);
  // Keep the file's own coordinates: SAGrid does the up-axis turn itself (labels are written in
  // the file's frame), so assimp's Collada z-up to y-up rotation must not happen.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  // Read first, post-process second: assimp's OBJ loader turns a two-vertex face ("f 4 5", as
  // some Sweet Home 3D models have) into a line without flagging its mesh as holding lines, and
  // the validator then refuses the whole file (assimp issue 2554). With the flags recomputed
  // from the faces, SortByPType drops the lines and validation checks the rest.
  const aiScene* scene = importer.ReadFile(parsedPath.string(), 0);
  // What the loader parsed, before triangulation: the partial-read check compares this with what
  // the file declares. Triangulation may then lose triangles of polygons that are not simple (a
  // Sweet Home 3D fridge's 32-gons), which is not a cut file.
  std::size_t trianglesParsed = 0;
  if (scene) {
    trianglesParsed = parsedTriangles(*scene);
    recomputePrimitiveTypes(*scene);
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                         aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  }
  // Past the deadline the result is refused even where the loader finished: the limit is the
  // user's (most loaders ignore the cancel).
  if (deadline.expired()) throw FileError(path, deadline.problem());
  if (!scene) {
    const std::string reason = oneLine(importer.GetErrorString());
    // Assimp's validator rejects meshes without faces; say it in the user's terms.
    if (reason.find("contains no faces") != std::string::npos) {
      throw FileError(path, "contains no triangles (empty scene)");
    }
    // SortByPType dropped every mesh: all were lines or points.
    if (reason.find("No meshes remaining") != std::string::npos) {
      throw FileError(path, "contains no triangles (only lines or points)");
    }
    throw FileError(path, "cannot be read as " + extension.substr(1) + ": " + reason);
  }
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode) {
    throw FileError(path, "contains no triangles (empty or incomplete scene)");
  }

  Mesh mesh;
  mesh.sha256 = sha256.get();
  MaterialReader(*scene, path, mesh).readAll();
  GeometryMerger merger(*scene, mesh);
  merger.merge();
  if (mesh.triangles.empty()) throw FileError(path, "contains no triangles");
  reportPartialRead(path, facts, trianglesParsed, options.lenient);
  if (mesh.triangles.size() < trianglesParsed)
    logger()->warn("{}: {} of {} triangles lost when triangulating polygons (not simple)",
                   path.string(), trianglesParsed - mesh.triangles.size(), trianglesParsed);

  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    if (!mesh.positions[v].allFinite()) {
      throw FileError(path, "has NaN or infinite coordinates (vertex " + std::to_string(v + 1) + ")");
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (!isSaneCoordinate(mesh.positions[v][axis])) {
        char value[32];
        std::snprintf(value, sizeof value, "%g", double(mesh.positions[v][axis]));
        throw FileError(path, "has coordinate " + std::string(value) + " at vertex " +
                                  std::to_string(v + 1) + "; coordinates must be within +-1e9");
      }
    }
  }
  if (const std::size_t removed = removeDegenerateTriangles(mesh)) {
    if (mesh.triangles.empty()) {
      throw FileError(path, "has only degenerate triangles (zero area), no surface");
    }
    logger()->info("{}: dropped {} degenerate triangles", path.string(), removed);
  }
  if (auto problem = normalizationProblem(mesh.bounds())) throw FileError(path, "mesh " + *problem);

  mesh.fileUp = options.up ? *options.up : defaultUpAxis(extension, *scene);
  const bool fixedByFormat = extension == ".gltf" || extension == ".glb";
  if (!options.up && options.detectUp && !fixedByFormat) {
    // Still in the file's frame here, so the detected axis is a file axis.
    const bool declares = extension == ".fbx" || extension == ".dae";
    const UpAxis unsure = declares ? mesh.fileUp : unsureUpAxis(extension);
    const UpAxisDetection detection = detectUpAxis(mesh, unsure);
    const float needed = declares ? kOverrideDeclaredUpConfidence : kMinDetectedUpConfidence;
    if (detection.axis == unsure || detection.confidence >= needed) {
      mesh.fileUp = detection.axis;
      mesh.fileUpConfidence = detection.confidence;
      mesh.fileUpDetected = true;
    } else if (!declares) {
      mesh.fileUp = unsure;
      mesh.fileUpConfidence = detection.probabilities[static_cast<std::size_t>(unsure)];
      mesh.fileUpDetected = true;  // looked at, kept the format's usual axis
    }
  }
  for (auto& p : mesh.positions) p = fileToZUp(p, mesh.fileUp);
  for (auto& n : mesh.normals) n = fileToZUp(n, mesh.fileUp);
  fillMissingNormals(mesh, merger.missingNormals());
  if (mesh.triangleMaterials.size() == mesh.triangles.size() && mesh.materials.empty()) {
    mesh.triangleMaterials.clear();
  }
  logger()->info("{}: {} triangles, {} vertices, {} materials, {} textures, {}-up", path.string(),
                 mesh.triangleCount(), mesh.vertexCount(), mesh.materials.size(),
                 mesh.textures.size(), toString(mesh.fileUp));
  return mesh;
}

}  // namespace sagrid
