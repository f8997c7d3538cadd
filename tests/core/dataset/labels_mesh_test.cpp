// Reader-side containment (issue 14): a labels file's object.mesh and a manifest's mesh/labels
// never make SAGrid read outside the folder they belong to, or the wider root a caller named.
#include "core/dataset/labels_mesh.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/dataset/dataset.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;
using namespace std::string_literals;

void touch(const fs::path& file) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "x";
}

ObjectLabels labelsNaming(const std::string& mesh) {
  ObjectLabels labels;
  labels.object.id = "obj";
  labels.object.mesh = mesh;
  return labels;
}

// The message names the labels file first (one clear line).
void expectRefused(const ObjectLabels& labels, const fs::path& labelsPath,
                   const fs::path& meshRoot = {}) {
  try {
    const fs::path mesh = meshForLabels(labels, labelsPath, meshRoot);
    ADD_FAILURE() << "accepted object.mesh '" << labels.object.mesh.substr(0, 60) << "' as "
                  << mesh;
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(labelsPath.string() + ": refusing", 0), 0u)
        << e.what();
  }
}

const std::vector<std::string>& hostileReferences() {
  static const std::vector<std::string> references = {
      "../../../../etc/hostname", "/etc/hostname",       "mesh\0.glb"s,
      "\\etc\\hostname",          "C:\\windows\\x.glb",  "sub/../../../../etc/hostname",
      "",                         std::string(300, 'm') + ".glb"};
  return references;
}

TEST(LabelsMesh, ObjectMeshBesideTheLabelsIsFound) {
  const fs::path dir = test::freshTempDir();
  touch(dir / "obj" / "mesh.glb");
  EXPECT_EQ(meshForLabels(labelsNaming("mesh.glb"), dir / "obj" / "labels.json"),
            dir / "obj" / "mesh.glb");
  EXPECT_EQ(meshForLabels(labelsNaming(""), dir / "obj" / "labels.json"),
            dir / "obj" / "mesh.glb");  // no object.mesh: the mesh beside it
}

TEST(LabelsMesh, AbsoluteClimbingAndNulReferencesAreRefused) {
  const fs::path dir = test::freshTempDir();
  const fs::path labelsPath = dir / "data" / "obj" / "labels.json";
  touch(dir / "data" / "obj" / "mesh.glb");
  for (const auto& reference : hostileReferences()) {
    if (reference.empty()) continue;  // empty object.mesh means "the mesh beside it"
    expectRefused(labelsNaming(reference), labelsPath);
    // Still refused with a mesh root: the root widens the folder, not the rule.
    expectRefused(labelsNaming(reference), labelsPath, dir / "data");
  }
  expectRefused(labelsNaming("../other/mesh.glb"), labelsPath);  // a sibling object: no root
}

// annotate --out OUT writes object.mesh relative to OUT/<id>/ ("../../data/x/mesh.glb"): read
// back with the data folder as mesh root (export --mesh-root), and only then.
TEST(LabelsMesh, WhatAnnotateOutWritesIsReadWithTheDataFolderAsMeshRoot) {
  const fs::path dir = test::freshTempDir();
  touch(dir / "data" / "x" / "mesh.glb");
  touch(dir / "secret.glb");
  const fs::path labelsPath = dir / "out" / "x" / "labels.json";
  const ObjectLabels labels = labelsNaming("../../data/x/mesh.glb");
  expectRefused(labels, labelsPath);
  EXPECT_EQ(meshForLabels(labels, labelsPath, dir / "data"), dir / "data" / "x" / "mesh.glb");
  EXPECT_EQ(fs::canonical(meshForLabels(labels, labelsPath, dir)),
            fs::canonical(dir / "data" / "x" / "mesh.glb"));
  // Out of the root again: refused, naming the labels file.
  expectRefused(labelsNaming("../../secret.glb"), labelsPath, dir / "data");
  expectRefused(labelsNaming("../../data/../secret.glb"), labelsPath, dir / "data");
  // A mesh beside the labels stays fine when a root is given.
  touch(dir / "out" / "x" / "own.glb");
  EXPECT_EQ(meshForLabels(labelsNaming("own.glb"), labelsPath, dir / "data"),
            dir / "out" / "x" / "own.glb");
}

TEST(LabelsMesh, ALinkLeadingOutOfTheRootIsRefused) {
  const fs::path dir = test::freshTempDir();
  touch(dir / "secret" / "mesh.glb");
  fs::create_directories(dir / "data");
  fs::create_directory_symlink(dir / "secret", dir / "data" / "x");
  expectRefused(labelsNaming("../../data/x/mesh.glb"), dir / "out" / "x" / "labels.json",
                dir / "data");
}

TEST(DatasetManifest, ReferencesOutsideTheDatasetAreRefusedNamingTheLine) {
  const fs::path root = test::freshTempDir();
  const fs::path dir = root / "set";
  touch(root / "outside" / "mesh.glb");
  fs::create_directories(dir);
  for (const auto& reference : hostileReferences()) {
    for (const char* field : {"mesh", "labels"}) {
      nlohmann::json line = {{"id", "a"}, {"mesh", "a/mesh.glb"}};
      line[field] = reference;
      std::ofstream(dir / "manifest.jsonl") << line.dump() << "\n";
      try {
        const auto entries = readDataset(dir);
        ADD_FAILURE() << field << " '" << reference.substr(0, 60) << "' accepted as "
                      << entries.at(0).mesh << " / " << entries.at(0).labels;
      } catch (const FileError& e) {
        EXPECT_THAT(e.what(), HasSubstr((dir / "manifest.jsonl").string() + " line 1: refusing"));
      }
    }
  }
  // An id that climbs is no way out either (the default labels path is built from it).
  std::ofstream(dir / "manifest.jsonl") << R"({"id":"../../outside","mesh":"a/mesh.glb"})"
                                        << "\n";
  EXPECT_THROW(readDataset(dir), FileError);
}

TEST(DatasetManifest, AReferenceRootTheCallerNamesWidensIt) {
  const fs::path root = test::freshTempDir();
  const fs::path subset = root / "work" / "fold1" / "test";
  fs::create_directories(subset);
  std::ofstream(subset / "manifest.jsonl")
      << R"({"id":"a","mesh":"../../../data/a/mesh.glb","labels":"../../../data/a/labels.json"})"
      << "\n";
  EXPECT_THROW(readDataset(subset), FileError);
  const auto entries = readDataset(subset, root / "data");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].mesh, root / "data" / "a" / "mesh.glb");
  EXPECT_EQ(entries[0].labels, root / "data" / "a" / "labels.json");
  std::ofstream(subset / "manifest.jsonl")
      << R"({"id":"a","mesh":"../../../secret/mesh.glb"})" << "\n";
  EXPECT_THROW(readDataset(subset, root / "data"), FileError);
}

}  // namespace
}  // namespace sagrid
