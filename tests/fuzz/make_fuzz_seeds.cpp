// Writes the seed corpora of the fuzz targets into OUT/<target>/: small meshes in every format
// (a cube written by assimp's exporters, the bundled samples and shared/data/real-dev OBJs, and
// a sample as GLB by our own encoder), labels.json files (tests/data, real-dev, one in the full
// schema), the shipped model cards, .npz/.npy files of every dtype, architecture strings.
// Usage: make_fuzz_seeds OUT SOURCE_DIR SHARED_DIR
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/io/npz.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_import.h"
#include "core/model/architecture.h"

namespace fs = std::filesystem;

namespace {

constexpr std::uintmax_t kMaxSeedBytes = 200 * 1024;  // larger inputs only slow the fuzzers

const char* kCubeObj =
    "# unit cube\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "vn 0 0 1\nvt 0 0\nvt 1 1\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
    "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";

void write(const fs::path& path, const std::string& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
}

void copySeed(const fs::path& from, const fs::path& toDir, const std::string& name) {
  std::error_code ec;
  if (!fs::is_regular_file(from, ec) || fs::file_size(from, ec) > kMaxSeedBytes) return;
  fs::create_directories(toDir);
  fs::copy_file(from, toDir / name, fs::copy_options::overwrite_existing, ec);
}

// Every format assimp can write that we import, from one scene.
void exportScene(const aiScene* scene, const fs::path& out, const std::string& name) {
  Assimp::Exporter exporter;
  const struct {
    const char* format;
    const char* folder;
    const char* extension;
  } formats[] = {{"ply", "mesh_ply", ".ply"},  {"plyb", "mesh_ply", ".b.ply"},
                 {"stl", "mesh_stl", ".stl"},  {"stlb", "mesh_stl", ".b.stl"},
                 {"glb2", "mesh_glb", ".glb"}, {"obj", "mesh_obj", ".obj"},
                 {"fbxa", "mesh_fbx", ".fbx"}, {"fbx", "mesh_fbx", ".b.fbx"}};
  for (const auto& f : formats) {
    const fs::path path = out / f.folder / (name + f.extension);
    fs::create_directories(path.parent_path());
    if (exporter.Export(scene, f.format, path.string()) != AI_SUCCESS)
      std::fprintf(stderr, "make_fuzz_seeds: %s: %s\n", path.c_str(), exporter.GetErrorString());
    std::error_code ec;
    if (fs::file_size(path, ec) > kMaxSeedBytes) fs::remove(path, ec);
  }
}

void meshSeeds(const fs::path& out, const fs::path& source, const fs::path& shared) {
  Assimp::Importer importer;
  const aiScene* cube =
      importer.ReadFileFromMemory(kCubeObj, std::strlen(kCubeObj), aiProcess_Triangulate, "obj");
  if (cube) exportScene(cube, out, "cube");
  write(out / "mesh_obj" / "cube_text.obj", kCubeObj);

  std::vector<fs::path> objs;
  // The wild pool's GLBs seed the glTF extensions (Draco, WebP) of core/mesh/gltf_plain.
  for (const fs::path root : {source / "resources" / "samples", shared / "data" / "real-dev",
                              source / "tests" / "data", shared / "data" / "wild-pool"}) {
    std::error_code ec;
    if (!fs::is_directory(root, ec)) continue;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      if (e.path().extension() == ".obj") objs.push_back(e.path());
      if (e.path().extension() == ".glb")
        copySeed(e.path(), out / "mesh_glb", e.path().parent_path().filename().string() + ".glb");
    }
  }
  int n = 0;
  for (const auto& obj : objs) {
    const std::string name = obj.parent_path().filename().string();
    copySeed(obj, out / "mesh_obj", name + ".obj");
    if (n++ >= 2) continue;  // other formats from the first few only
    Assimp::Importer sampleImporter;
    if (const aiScene* s = sampleImporter.ReadFile(obj.string(), aiProcess_Triangulate))
      exportScene(s, out, name);
    try {
      write(out / "mesh_glb" / (name + ".sagrid.glb"), sagrid::encodeGlb(sagrid::importMesh(obj)));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "make_fuzz_seeds: %s\n", e.what());
    }
  }
}

void labelSeeds(const fs::path& out, const fs::path& source, const fs::path& shared) {
  int n = 0;
  for (const fs::path root : {source / "tests" / "data", shared / "data" / "real-dev"}) {
    std::error_code ec;
    if (!fs::is_directory(root, ec)) continue;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      if (e.path().extension() == ".json")
        copySeed(e.path(), out / "labels",
                 std::to_string(n++) + "_" + e.path().filename().string());
    }
  }
  sagrid::ObjectLabels labels;
  labels.object.id = "stove_0001";
  labels.object.mesh = "mesh.glb";
  labels.object.category = "stove";
  labels.object.upConfidence = 0.8;
  sagrid::AffordancePoint p;
  p.type = "heatsource";
  p.position = {0.1f, -0.2f, 0.9f};
  p.normal = Eigen::Vector3f(0, 0, 1);
  p.confidence = 0.87f;
  p.source = "stove.heatsource@1a2b3c4d";
  labels.affordances = {p, p};
  labels.affordances[1].status = sagrid::AffordanceStatus::Edited;
  labels.reviewState = sagrid::ReviewState::Done;
  labels.reviewUpdated = "2026-11-21T10:00:00Z";
  write(out / "labels" / "full_schema.json", sagrid::toJson(labels).dump(2));
}

void modelSeeds(const fs::path& out, const fs::path& source) {
  for (const auto& e : fs::directory_iterator(source / "resources" / "models")) {
    if (e.path().extension() == ".json")
      copySeed(e.path(), out / "model_card", e.path().filename());
  }
  for (const std::string arch :
       {std::string(sagrid::model::kDefaultArchitecture),
        std::string(sagrid::model::kPaperCnn1Architecture), std::string("[3,1,16]"),
        std::string(" [1,0,8] , [5,2,4,1] "), std::string("sparse"), std::string("dense")}) {
    write(out / "architecture" / (std::to_string(std::hash<std::string>{}(arch)) + ".txt"), arch);
  }
}

void arraySeeds(const fs::path& out, const fs::path& source) {
  sagrid::NpzArchive archive;
  archive["u8"] = sagrid::NpyArray::from<std::uint8_t>({1, 2, 3, 4, 5, 6}, {2, 3});
  archive["i32"] = sagrid::NpyArray::from<std::int32_t>({-1, 7, 9});
  archive["i64"] = sagrid::NpyArray::from<std::int64_t>({1LL << 40});
  archive["f32"] = sagrid::NpyArray::from<float>({0.5f, -2.0f, 1e-3f, 4.0f}, {2, 2, 1});
  archive["f64"] = sagrid::NpyArray::from<double>({3.25}, {});
  archive["b"] = sagrid::NpyArray::from<bool>({true, false, true});
  fs::create_directories(out / "npz");
  fs::create_directories(out / "npy");
  sagrid::writeNpz(out / "npz" / "every_dtype.npz", archive);
  for (const auto& [name, array] : archive)
    write(out / "npy" / (name + ".npy"), sagrid::serializeNpy(array));
  copySeed(source / "tests" / "data" / "numpy_compressed.npz", out / "npz", "numpy_compressed.npz");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: make_fuzz_seeds OUT SOURCE_DIR SHARED_DIR\n");
    return 2;
  }
  const fs::path out = argv[1], source = argv[2], shared = argv[3];
  meshSeeds(out, source, shared);
  labelSeeds(out, source, shared);
  modelSeeds(out, source);
  arraySeeds(out, source);
  for (const auto& e : fs::directory_iterator(out)) {
    const auto n = std::distance(fs::directory_iterator(e.path()), fs::directory_iterator());
    std::printf("%-14s %ld seeds\n", e.path().filename().c_str(), static_cast<long>(n));
  }
  return 0;
}
