// glTF extensions of in-the-wild files (core/mesh/gltf_plain): each is built here with the same
// library a publisher would use (Draco, meshoptimizer, libwebp), read back through importMesh and
// compared with what was encoded; damaged files give one error naming the file and the problem.
#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <webp/encode.h>

#include <array>
#include <cmath>

#include "core/mesh/gltf_plain.h"
#include "core/mesh/mesh_import.h"
#include "support/gltf_files.h"
#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using test::appendAligned;
using test::bytesOf;
using test::glbBytes;
using test::importError;
using test::writeFile;
using ::testing::HasSubstr;

// A box 0.6 x 0.4 x 0.9 (file frame, y up) with per-vertex uvs.
struct Box {
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<float, 2>> uvs;
  std::vector<std::uint32_t> indices;
};

Box box() {
  Box b;
  for (int i = 0; i < 8; ++i) {
    b.positions.push_back({i & 1 ? 0.6f : 0.0f, i & 2 ? 0.9f : 0.0f, i & 4 ? 0.4f : 0.0f});
    b.uvs.push_back({i & 1 ? 1.0f : 0.0f, i & 2 ? 0.75f : 0.25f});
  }
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    for (int t : {1, 2}) {  // (0 1 2) and (0 2 3)
      b.indices.push_back(f[0]);
      b.indices.push_back(f[t]);
      b.indices.push_back(f[t + 1]);
    }
  }
  return b;
}

json baseDocument() {
  return json{{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", json::array({{{"nodes", {0}}}})},
              {"nodes", json::array({{{"mesh", 0}}})}};
}

// The file's own coordinates of an imported y-up mesh (import turns y-up into z-up: (x, -z, y)).
Eigen::Vector3f fileFrame(const Eigen::Vector3f& p) { return {p.x(), p.z(), -p.y()}; }

// Every imported vertex lies within `tolerance` of a box corner, and every corner is reached.
void expectBoxCorners(const Mesh& mesh, float tolerance) {
  const Box b = box();
  ASSERT_EQ(mesh.triangleCount(), 12u);
  std::vector<bool> reached(b.positions.size(), false);
  for (const auto& p : mesh.positions) {
    const Eigen::Vector3f q = fileFrame(p);
    float best = 1e9f;
    std::size_t nearest = 0;
    for (std::size_t c = 0; c < b.positions.size(); ++c) {
      const float d = (q - Eigen::Vector3f(b.positions[c][0], b.positions[c][1], b.positions[c][2])).norm();
      if (d < best) best = d, nearest = c;
    }
    EXPECT_LE(best, tolerance) << q.transpose();
    reached[nearest] = true;
  }
  EXPECT_EQ(std::count(reached.begin(), reached.end(), true), 8);
}

// --- Draco

struct DracoBox {
  std::string bytes;
  std::size_t points = 0;
  int positionId = -1, uvId = -1;
};

DracoBox encodeDracoBox(int positionBits) {
  const Box b = box();
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(static_cast<int>(b.indices.size() / 3));
  const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int tex = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  for (std::size_t f = 0; f < b.indices.size() / 3; ++f) {
    const auto& i = b.indices;
    builder.SetAttributeValuesForFace(pos, draco::FaceIndex(static_cast<std::uint32_t>(f)),
                                      b.positions[i[3 * f]].data(), b.positions[i[3 * f + 1]].data(),
                                      b.positions[i[3 * f + 2]].data());
    builder.SetAttributeValuesForFace(tex, draco::FaceIndex(static_cast<std::uint32_t>(f)), b.uvs[i[3 * f]].data(),
                                      b.uvs[i[3 * f + 1]].data(), b.uvs[i[3 * f + 2]].data());
  }
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, positionBits);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
  draco::EncoderBuffer buffer;
  EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &buffer).ok());
  DracoBox out;
  out.bytes.assign(buffer.data(), buffer.size());
  out.positionId = static_cast<int>(mesh->attribute(pos)->unique_id());
  out.uvId = static_cast<int>(mesh->attribute(tex)->unique_id());
  draco::DecoderBuffer in;  // the point count a publisher's accessors declare: the decoded one
  in.Init(out.bytes.data(), out.bytes.size());
  out.points = draco::Decoder().DecodeMeshFromBuffer(&in).value()->num_points();
  return out;
}

json dracoDocument(const DracoBox& draco, std::size_t declaredPoints, std::size_t byteLength) {
  json d = baseDocument();
  d["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  d["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  d["meshes"] = json::array({{{"primitives", json::array({{
      {"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"mode", 4},
      {"extensions", {{"KHR_draco_mesh_compression",
                       {{"bufferView", 0}, {"attributes", {{"POSITION", draco.positionId}, {"TEXCOORD_0", draco.uvId}}}}}}}}})}}});
  d["accessors"] = json::array({{{"componentType", 5126}, {"count", declaredPoints}, {"type", "VEC3"},
                                 {"min", {0, 0, 0}}, {"max", {0.6, 0.9, 0.4}}},
                                {{"componentType", 5126}, {"count", declaredPoints}, {"type", "VEC2"}},
                                {{"componentType", 5125}, {"count", 36}, {"type", "SCALAR"}}});
  d["bufferViews"] = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", byteLength}}});
  d["buffers"] = json::array({{{"byteLength", byteLength}}});
  return d;
}

TEST(GltfPlain, DracoCompressedGlbReadsItsTrianglesWithinTheQuantizationStep) {
  const DracoBox draco = encodeDracoBox(14);
  const fs::path path = writeFile(test::freshTempDir() / "box.glb",
                                  glbBytes(dracoDocument(draco, draco.points, draco.bytes.size()), draco.bytes));
  const Mesh mesh = importMesh(path);
  // 14 bits over the largest extent (0.9): a step of 0.9 / 16383.
  expectBoxCorners(mesh, 0.9f / 16383.0f * 1.01f);
  ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
}

TEST(GltfPlain, DracoInAGltfWithAnExternalBufferReadsToo) {
  const DracoBox draco = encodeDracoBox(11);
  const fs::path dir = test::freshTempDir();
  json d = dracoDocument(draco, draco.points, draco.bytes.size());
  d["buffers"][0]["uri"] = "box%20data.bin";  // percent-escaped, as exporters write spaces
  writeFile(dir / "box data.bin", draco.bytes);
  const Mesh mesh = importMesh(writeFile(dir / "box.gltf", d.dump()));
  expectBoxCorners(mesh, 0.9f / 2047.0f * 1.01f);
}

TEST(GltfPlain, TruncatedDracoDataIsOneErrorNamingDraco) {
  const DracoBox draco = encodeDracoBox(14);
  const std::string half = draco.bytes.substr(0, draco.bytes.size() / 2);
  const fs::path path =
      writeFile(test::freshTempDir() / "cut.glb", glbBytes(dracoDocument(draco, draco.points, half.size()), half));
  const std::string error = importError(path);
  EXPECT_THAT(error, HasSubstr("KHR_draco_mesh_compression"));
  EXPECT_THAT(error, HasSubstr("corrupt or truncated"));
}

TEST(GltfPlain, DracoCountsThatDisagreeWithTheAccessorsAreAnError) {
  const DracoBox draco = encodeDracoBox(14);
  const fs::path path = writeFile(test::freshTempDir() / "count.glb",
                                  glbBytes(dracoDocument(draco, draco.points + 5, draco.bytes.size()), draco.bytes));
  EXPECT_THAT(importError(path), HasSubstr("declares " + std::to_string(draco.points + 5) +
                                           " values but the Draco data decodes " + std::to_string(draco.points)));
}

// --- EXT_meshopt_compression with KHR_mesh_quantization

// Positions as int16 millimetres (a node scale of 0.001 makes metres), uvs as normalized uint16;
// both vertex streams and the indices compressed, the uncompressed buffer a fallback with no data.
std::string meshoptBoxGlb(bool corrupt, std::size_t declaredVertices = 8) {
  const Box b = box();
  std::vector<std::int16_t> positions;  // stride 8: x y z + padding
  std::vector<std::uint16_t> uvs;
  for (std::size_t v = 0; v < b.positions.size(); ++v) {
    for (int c = 0; c < 3; ++c) positions.push_back(static_cast<std::int16_t>(std::lround(b.positions[v][c] * 1000)));
    positions.push_back(0);
    for (int c = 0; c < 2; ++c) uvs.push_back(static_cast<std::uint16_t>(std::lround(b.uvs[v][c] * 65535)));
  }
  auto encodeVertices = [](const void* data, std::size_t count, std::size_t stride) {
    std::string out(meshopt_encodeVertexBufferBound(count, stride), '\0');
    out.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(out.data()), out.size(), data, count, stride));
    return out;
  };
  std::string indices(meshopt_encodeIndexBufferBound(b.indices.size(), 8), '\0');
  indices.resize(meshopt_encodeIndexBuffer(reinterpret_cast<unsigned char*>(indices.data()), indices.size(),
                                           b.indices.data(), b.indices.size()));
  std::string bin;
  const std::string p = encodeVertices(positions.data(), 8, 8), t = encodeVertices(uvs.data(), 8, 4);
  const std::size_t pAt = appendAligned(bin, corrupt ? std::string(p.size(), '\x7f') : p);
  const std::size_t tAt = appendAligned(bin, t);
  const std::size_t iAt = appendAligned(bin, indices);
  auto view = [&](std::size_t at, std::size_t length, std::size_t stride, std::size_t count, const char* mode,
                  std::size_t fallbackOffset) {
    json v{{"buffer", 1}, {"byteOffset", fallbackOffset}, {"byteLength", stride * count},
           {"extensions", {{"EXT_meshopt_compression", {{"buffer", 0}, {"byteOffset", at}, {"byteLength", length},
                                                        {"byteStride", stride}, {"count", count}, {"mode", mode}}}}}};
    if (std::string(mode) == "ATTRIBUTES") v["byteStride"] = stride;
    return v;
  };
  json d = baseDocument();
  d["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
  d["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
  d["nodes"][0]["scale"] = {0.001, 0.001, 0.001};
  d["meshes"] = json::parse(R"([{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2}]}])");
  d["accessors"] = json::array({{{"bufferView", 0}, {"componentType", 5122}, {"count", declaredVertices}, {"type", "VEC3"},
                                 {"min", {0, 0, 0}}, {"max", {600, 900, 400}}},
                                {{"bufferView", 1}, {"componentType", 5123}, {"normalized", true}, {"count", 8}, {"type", "VEC2"}},
                                {{"bufferView", 2}, {"componentType", 5125}, {"count", 36}, {"type", "SCALAR"}}});
  d["bufferViews"] = json::array({view(pAt, p.size(), 8, 8, "ATTRIBUTES", 0), view(tAt, t.size(), 4, 8, "ATTRIBUTES", 64),
                                  view(iAt, indices.size(), 4, 36, "TRIANGLES", 96)});
  d["buffers"] = json::array({{{"byteLength", bin.size()}},
                              {{"byteLength", 96 + 144}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}});
  return glbBytes(d, bin);
}

TEST(GltfPlain, MeshoptCompressedQuantizedGlbReadsItsTrianglesWithinTheQuantizationStep) {
  const Mesh mesh = importMesh(writeFile(test::freshTempDir() / "meshopt.glb", meshoptBoxGlb(false)));
  expectBoxCorners(mesh, 0.0005f);  // a millimetre grid
  ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
  for (const auto& uv : mesh.uvs) EXPECT_NEAR(std::fmod(uv.y() + 1.0f, 0.5f), 0.25f, 1e-4f);  // v 0.25 or 0.75
}

TEST(GltfPlain, CorruptMeshoptDataAndAQuantizedAccessorPastItsViewAreErrors) {
  const fs::path dir = test::freshTempDir();
  EXPECT_THAT(importError(writeFile(dir / "corrupt.glb", meshoptBoxGlb(true))),
              HasSubstr("buffer view 0 (EXT_meshopt_compression) does not decode"));
  EXPECT_THAT(importError(writeFile(dir / "range.glb", meshoptBoxGlb(false, 9))),
              HasSubstr("accessor 0 reads past the end of its buffer view"));
}

// --- WebP textures and KHR_texture_transform

// A 2x2 image, red green / blue white, as lossless WebP.
std::string webp2x2() {
  const std::uint8_t rgba[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  std::uint8_t* out = nullptr;
  const std::size_t size = WebPEncodeLosslessRGBA(rgba, 2, 2, 8, &out);
  std::string bytes(reinterpret_cast<const char*>(out), size);
  WebPFree(out);
  return bytes;
}

// One textured triangle; `image` embedded as image/webp behind EXT_texture_webp, and the base
// colour texture's transform when given: the document and its binary buffer.
std::pair<json, std::string> texturedTriangle(const std::string& image, const std::array<float, 6>& uvs,
                                              const json& transform) {
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::string bin;
  const std::size_t pAt = appendAligned(bin, bytesOf(positions, 9));
  const std::size_t tAt = appendAligned(bin, bytesOf(uvs.data(), 6));
  const std::size_t iAt = appendAligned(bin, image);
  json d = baseDocument();
  d["extensionsUsed"] = {"EXT_texture_webp"};
  json baseColor{{"index", 0}};
  if (!transform.is_null()) {
    d["extensionsUsed"].push_back("KHR_texture_transform");
    baseColor["extensions"] = {{"KHR_texture_transform", transform}};
  }
  d["meshes"] = json::parse(R"([{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}])");
  d["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", baseColor}}}}});
  d["textures"] = json::array({{{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}}});
  d["images"] = json::array({{{"bufferView", 2}, {"mimeType", "image/webp"}}});
  d["accessors"] = json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                                 {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                                {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}});
  d["bufferViews"] = json::array({{{"buffer", 0}, {"byteOffset", pAt}, {"byteLength", 36}},
                                  {{"buffer", 0}, {"byteOffset", tAt}, {"byteLength", 24}},
                                  {{"buffer", 0}, {"byteOffset", iAt}, {"byteLength", image.size()}}});
  d["buffers"] = json::array({{{"byteLength", bin.size()}}});
  return {d, bin};
}

std::string texturedTriangleGlb(const std::string& image, const std::array<float, 6>& uvs, const json& transform) {
  const auto [document, binary] = texturedTriangle(image, uvs, transform);
  return glbBytes(document, binary);
}

TEST(GltfPlain, AWebpTextureDecodesToItsPixels) {
  const Mesh mesh = importMesh(writeFile(test::freshTempDir() / "webp.glb",
                                         texturedTriangleGlb(webp2x2(), {0.25f, 0.25f, 0.25f, 0.25f, 0.25f, 0.25f}, nullptr)));
  ASSERT_EQ(mesh.textures.size(), 1u);
  ASSERT_EQ(mesh.textures[0].width, 2);
  const std::vector<std::uint8_t> expected{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  EXPECT_EQ(mesh.textures[0].rgba, expected);
}

TEST(GltfPlain, ATextureTransformIsBakedIntoTheUvs) {
  const fs::path dir = test::freshTempDir();
  // offset (0.5, 0.25), rotation 90 degrees, scale (0.5, 2): uv' = T R S uv with the spec's R.
  const json transform{{"offset", {0.5, 0.25}}, {"rotation", M_PI / 2}, {"scale", {0.5, 2.0}}};
  const std::array<float, 6> uvs{0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};
  std::array<float, 6> expected{};
  for (int i = 0; i < 3; ++i) {
    const double u = uvs[2 * i] * 0.5, v = uvs[2 * i + 1] * 2.0;  // scale, then the spec's rotation
    expected[2 * i] = static_cast<float>(std::cos(M_PI / 2) * u + std::sin(M_PI / 2) * v + 0.5);
    expected[2 * i + 1] = static_cast<float>(-std::sin(M_PI / 2) * u + std::cos(M_PI / 2) * v + 0.25);
  }
  const Mesh transformed = importMesh(writeFile(dir / "t.glb", texturedTriangleGlb(webp2x2(), uvs, transform)));
  const Mesh baked = importMesh(writeFile(dir / "b.glb", texturedTriangleGlb(webp2x2(), expected, nullptr)));
  ASSERT_EQ(transformed.uvs.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(transformed.uvs[i].isApprox(baked.uvs[i], 1e-5f)) << transformed.uvs[i].transpose();
}

TEST(GltfPlain, AWebpThatDoesNotDecodeIsAnError) {
  const std::string broken = "RIFF\x20\x00\x00\x00WEBPVP8L" + std::string(24, '\x11');
  EXPECT_THAT(importError(writeFile(test::freshTempDir() / "bad.glb",
                                    texturedTriangleGlb(broken, {0, 0, 1, 0, 0, 1}, nullptr))),
              HasSubstr("glTF image 0 is a WebP image that does not decode"));
}

TEST(GltfPlain, AnImagePathLeavingTheObjectsFolderIsAnError) {
  const fs::path dir = test::freshTempDir();
  writeFile(dir / "outside.webp", webp2x2());
  auto [document, binary] = texturedTriangle(webp2x2(), {0, 0, 1, 0, 0, 1}, nullptr);
  document["images"][0] = {{"uri", "../outside.webp"}};
  document["buffers"][0]["uri"] = "tri.bin";
  fs::create_directories(dir / "object");
  writeFile(dir / "object" / "tri.bin", binary);
  EXPECT_THAT(importError(writeFile(dir / "object" / "tri.gltf", document.dump())), HasSubstr("../outside.webp"));
}

TEST(GltfPlain, AnExtensionSagridCannotReadIsNamedInTheError) {
  json d = baseDocument();
  d["extensionsUsed"] = {"KHR_texture_basisu"};
  d["extensionsRequired"] = {"KHR_texture_basisu"};
  d["meshes"] = json::parse(R"([{"primitives": [{"attributes": {"POSITION": 0}}]}])");
  d["accessors"] = json::array({{{"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}});
  EXPECT_THAT(importError(writeFile(test::freshTempDir() / "basisu.gltf", d.dump())),
              HasSubstr("requires the glTF extension KHR_texture_basisu, which SAGrid cannot read"));
}

TEST(GltfPlain, APlainGltfIsLeftToAssimpUnchanged) {
  json d = baseDocument();
  d["extensionsUsed"] = {"KHR_materials_clearcoat"};
  EXPECT_FALSE(plainGlbOf(d.dump(), "plain.gltf").has_value());
  d["extensionsUsed"].push_back("KHR_mesh_quantization");
  d["meshes"] = json::parse(R"([{"primitives": [{"attributes": {"POSITION": 0}}]}])");
  d["accessors"] = json::array({{{"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}});
  EXPECT_TRUE(plainGlbOf(d.dump(), "quantized.gltf").has_value());
}

}  // namespace
}  // namespace sagrid

namespace sagrid {
namespace {

TEST(GltfPlain, AHostileCountIsRefusedBeforeAnythingIsAllocated) {
  json d = baseDocument();
  d["extensionsUsed"] = {"KHR_mesh_quantization"};
  d["meshes"] = json::parse(R"([{"primitives": [{"attributes": {"POSITION": 0}}]}])");
  d["accessors"] = json::array({{{"componentType", 5126}, {"count", 1u << 30}, {"type", "MAT4"}}});
  EXPECT_THAT(test::importError(test::writeFile(test::freshTempDir() / "huge.gltf", d.dump())),
              ::testing::HasSubstr("glTF accessor 0 declares an implausible count"));
}

}  // namespace
}  // namespace sagrid
