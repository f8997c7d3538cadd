// Issue 14: FBX files whose model hierarchy nests 20,000 deep overflowed the stack in assimp's
// FBX converter (SIGSEGV in every importing subcommand). Now the hierarchy, the record nesting and
// the binary record offsets are checked before assimp parses anything.
#include "core/mesh/fbx_structure_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/common/error.h"
#include "core/io/little_endian.h"
#include "core/mesh/mesh_import.h"
#include "support/fbx_files.h"
#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using test::importError;
using test::writeFile;
using ::testing::HasSubstr;

using Links = test::FbxLinks;
using test::asciiFbx;
using test::nestedAsciiFbx;

Links chain(int depth) { return test::fbxChain(depth); }

// Binary FBX 7400 (32-bit offsets): records are built inside out.
struct Record {
  std::string name;
  std::string properties;  // encoded
  std::size_t propertyCount = 0;
  std::vector<Record> children;
};

using io::put32;
using io::put64;

Record withProperties(std::string name, const std::string& text, std::vector<std::int64_t> ids) {
  Record r{std::move(name), {}, 0, {}};
  if (!text.empty()) {
    r.properties += 'S';
    put32(r.properties, static_cast<std::uint32_t>(text.size()));
    r.properties += text;
    ++r.propertyCount;
  }
  for (std::int64_t id : ids) {
    r.properties += 'L';
    put64(r.properties, static_cast<std::uint64_t>(id));
    ++r.propertyCount;
  }
  return r;
}

void writeRecord(std::string& out, const Record& r) {
  const std::size_t start = out.size();
  out.append(12, '\0');  // end offset, property count, property bytes: filled below
  out += static_cast<char>(r.name.size());
  out += r.name;
  out += r.properties;
  for (const Record& c : r.children) writeRecord(out, c);
  if (!r.children.empty()) out.append(13, '\0');
  std::string header;
  put32(header, static_cast<std::uint32_t>(out.size()));
  put32(header, static_cast<std::uint32_t>(r.propertyCount));
  put32(header, static_cast<std::uint32_t>(r.properties.size()));
  out.replace(start, 12, header);
}

std::string binaryFbx(const std::vector<Record>& top) {
  std::string out("Kaydara FBX Binary  \0\x1a\0", 23);
  put32(out, 7400);
  for (const Record& r : top) writeRecord(out, r);
  out.append(13, '\0');
  return out;
}

std::string binaryFbx(int models, const Links& links) {
  Record objects{"Objects", {}, 0, {}}, connections{"Connections", {}, 0, {}};
  for (int m = 0; m < models; ++m)
    objects.children.push_back(withProperties("Model", "", {100 + m}));
  for (const auto& [child, parent] : links)
    connections.children.push_back(withProperties("C", "OO", {child, parent}));
  return binaryFbx({objects, connections});
}

std::string checkError(const std::string& bytes, bool binary) {
  try {
    checkFbxStructure(bytes, binary, "scene.fbx");
  } catch (const FileError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

TEST(FbxStructureCheck, AsciiModelsNested20000DeepAreRefusedBeforeAssimpRecurses) {
  const fs::path dir = test::freshTempDir();
  const fs::path deep = writeFile(dir / "deep.fbx", nestedAsciiFbx(20000));
  EXPECT_THAT(importError(deep), HasSubstr("nests its FBX models more than 256 levels deep"));
  // A reasonable hierarchy still imports.
  const Mesh mesh = importMesh(writeFile(dir / "ok.fbx", nestedAsciiFbx(50)));
  EXPECT_EQ(mesh.triangles.size(), 1u);
  EXPECT_NO_THROW(checkFbxStructure(nestedAsciiFbx(256), false, "scene.fbx"));
  EXPECT_THAT(checkError(nestedAsciiFbx(257), false), HasSubstr("more than 256 levels"));
}

TEST(FbxStructureCheck, CyclesAndExponentialSharingAreRefused) {
  const Links cycle{{100, 0}, {101, 100}, {102, 101}, {101, 102}};
  EXPECT_THAT(checkError(asciiFbx(3, cycle, 102), false), HasSubstr("their own ancestors"));
  EXPECT_THAT(checkError(binaryFbx(3, cycle), true), HasSubstr("their own ancestors"));
  // 40 levels of two models, each the child of both models of the level above: 2^40 paths.
  Links diamond{{100, 0}, {101, 0}};
  for (int level = 1; level < 40; ++level)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        diamond.push_back({100 + 2 * level + a, 100 + 2 * (level - 1) + b});
  EXPECT_THAT(checkError(asciiFbx(80, diamond, 179), false),
              HasSubstr("more than 1000000 instances"));
  // A few shared parents are fine.
  EXPECT_NO_THROW(checkFbxStructure(asciiFbx(4, {{100, 0}, {101, 0}, {102, 100}, {102, 101}}, 102),
                                    false, "scene.fbx"));
}

TEST(FbxStructureCheck, AsciiBlocksNestedTooDeepAreRefused) {
  std::string text = "; FBX 7.4.0 project file\n";
  for (int i = 0; i < 300; ++i) text += "Block: {\n";
  EXPECT_THAT(checkError(text, false), HasSubstr("nests its FBX blocks more than 256"));
}

TEST(FbxStructureCheck, BinaryModelHierarchyAndRecordNestingAreBounded) {
  EXPECT_NO_THROW(checkFbxStructure(binaryFbx(100, chain(100)), true, "scene.fbx"));
  EXPECT_THAT(checkError(binaryFbx(20000, chain(20000)), true),
              HasSubstr("nests its FBX models more than 256 levels deep"));
  Record nested{"Leaf", {}, 0, {}};
  for (int i = 0; i < 300; ++i) nested = Record{"Level", {}, 0, {nested}};
  EXPECT_THAT(checkError(binaryFbx({nested}), true),
              HasSubstr("nests its FBX records more than 256"));
}

TEST(FbxStructureCheck, BinaryRecordOffsetsMustStayInsideTheFileAndTheirParent) {
  std::string bytes = binaryFbx(3, chain(3));
  const std::string good = bytes;
  put32(bytes, 0);  // some bytes of slack after the top level are allowed
  EXPECT_NO_THROW(checkFbxStructure(bytes, true, "scene.fbx"));
  bytes = good;
  bytes.replace(27, 4, std::string("\xff\xff\xff\x7f", 4));  // first record ends past the file
  EXPECT_THAT(checkError(bytes, true), HasSubstr("declares an end outside the file or its parent"));
  bytes = good;
  bytes.replace(27 + 8, 4, std::string("\xff\xff\xff\xff", 4));  // property bytes overflow
  EXPECT_THAT(checkError(bytes, true), HasSubstr("declares an end outside"));
  EXPECT_THAT(checkError(good.substr(0, 20), true), HasSubstr("header is truncated"));
  // Through the importer: the file is named and nothing reaches assimp.
  const fs::path path =
      writeFile(test::freshTempDir() / "deep.fbx", binaryFbx(20000, chain(20000)));
  EXPECT_THAT(importError(path), HasSubstr("nests its FBX models more than 256 levels deep"));
}

}  // namespace
}  // namespace sagrid
