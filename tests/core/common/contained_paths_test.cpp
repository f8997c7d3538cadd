// Containment of data-chosen names and references (issue 14): safe file names and references
// resolved inside the object's folder, attacked with absolute paths, ../ chains, NUL bytes,
// markup characters, 300-character names and symbolic links.
#include "core/common/contained_paths.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/common/error.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
using namespace std::string_literals;

TEST(SafeFileName, KeepsPlainNames) {
  EXPECT_EQ(safeFileName("flat_stove-01.v2"), "flat_stove-01.v2");
  EXPECT_EQ(safeFileName(""), "object");
  EXPECT_EQ(safeFileName("", 64, "mesh"), "mesh");
}

TEST(SafeFileName, NoSeparatorsDotsNulOrMarkup) {
  for (const std::string hostile :
       {"../../etc/passwd"s, "/etc/hostname"s, "..\\..\\windows"s, "a\0b"s, "<x>\"&'"s, ".."s, "."s,
        ".hidden"s, "C:evil"s, "a b\tc\n"s,
        "K\xc3\xbc"
        "che"s}) {
    const std::string name = safeFileName(hostile);
    SCOPED_TRACE(name);
    EXPECT_FALSE(name.empty());
    EXPECT_EQ(name.find('/'), std::string::npos);
    EXPECT_EQ(name.find('\\'), std::string::npos);
    EXPECT_EQ(name.find('\0'), std::string::npos);
    EXPECT_EQ(name.find_first_of("<>\"&': \t\n"), std::string::npos);
    EXPECT_NE(name.front(), '.');
    for (unsigned char c : name) EXPECT_LT(c, 0x80);
  }
  EXPECT_EQ(safeFileName("../../etc/passwd"), "_.._etc_passwd");
}

TEST(SafeFileName, LongNamesBoundedDeterministicDistinct) {
  const std::string a(300, 'a');
  const std::string b = std::string(299, 'a') + "b";
  EXPECT_EQ(safeFileName(a).size(), kMaxSafeFileNameLength);
  EXPECT_EQ(safeFileName(a), safeFileName(a));
  EXPECT_NE(safeFileName(a), safeFileName(b));
  EXPECT_EQ(safeFileName(a, 20).size(), 20u);
}

TEST(UniqueFileNames, CollisionFreeInOneRunAndCaseInsensitive) {
  UniqueFileNames names;
  EXPECT_EQ(names.claim("stove"), "stove");
  EXPECT_EQ(names.claim("stove"), "stove-2");
  EXPECT_EQ(names.claim("Stove"), "Stove-3");
  EXPECT_EQ(names.claim("a/b"), "a_b");
  EXPECT_EQ(names.claim("a_b"), "a_b-2");
  UniqueFileNames bounded(12);
  const std::string first = bounded.claim(std::string(300, 'x'));
  const std::string second = bounded.claim(std::string(300, 'x'));
  EXPECT_NE(first, second);
  EXPECT_LE(second.size(), 12u);
}

class ResolveContained : public ::testing::Test {
 protected:
  void SetUp() override {
    m_root = test::freshTempDir();
    m_object = m_root / "object";
    fs::create_directories(m_object / "textures");
    std::ofstream(m_root / "secret.txt") << "outside";
    std::ofstream(m_object / "textures" / "wood.png") << "png";
  }
  fs::path m_root, m_object;
};

TEST_F(ResolveContained, AcceptsNamesInsideTheFolder) {
  const fs::path mtl = m_object / "mesh.mtl";
  EXPECT_EQ(resolveContained(m_object, "textures/wood.png", mtl), m_object / "textures/wood.png");
  EXPECT_EQ(resolveContained(m_object, "textures\\wood.png", mtl), m_object / "textures/wood.png");
  EXPECT_EQ(resolveContained(m_object, "./a/../mesh.mtl", mtl), m_object / "mesh.mtl");
}

TEST_F(ResolveContained, RefusesEverythingElseNamingTheReferencingFile) {
  const fs::path labels = m_object / "labels.json";
  const std::string longClimb = [] {
    std::string s;
    for (int i = 0; i < 100; ++i) s += "../";
    return s + "etc/hostname";
  }();
  for (const std::string hostile :
       {"/etc/hostname"s, "\\etc\\hostname"s, "C:\\x.png"s, "../secret.txt"s,
        "textures/../../secret.txt"s, longClimb, "mesh\0.obj"s, ""s, "."s, "a/.."s,
        std::string(300, 'm') + ".obj"}) {
    SCOPED_TRACE(hostile);
    try {
      resolveContained(m_object, hostile, labels);
      ADD_FAILURE() << "accepted";
    } catch (const FileError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(labels.string(), 0), 0u) << e.what();
    }
  }
}

TEST_F(ResolveContained, RefusesSymbolicLinksLeadingOut) {
  std::error_code ec;
  fs::create_directory_symlink(m_root, m_object / "up", ec);
  fs::create_symlink(m_root / "secret.txt", m_object / "secret_link.txt", ec);
  if (ec) GTEST_SKIP() << "symbolic links unavailable: " << ec.message();
  EXPECT_THROW(resolveContained(m_object, "up/secret.txt", m_object / "mesh.obj"), FileError);
  EXPECT_THROW(resolveContained(m_object, "secret_link.txt", m_object / "mesh.obj"), FileError);
  EXPECT_TRUE(isInsideFolder(m_object / "textures" / "new.png", m_object));
  EXPECT_FALSE(isInsideFolder(m_root / "objectX", m_object));
}

}  // namespace
}  // namespace sagrid
