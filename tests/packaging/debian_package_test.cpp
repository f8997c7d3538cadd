// The Debian package (issue 13): `cpack -G DEB` from this build tree, its contents and declared
// dependencies, then the binary run from a `dpkg -x` root, from a working directory with no
// resources/ folder: --version, annotate on a bundled sample with the bundled models, which it
// must find beside itself (<root>/usr/bin/../share/sagrid), not in the source tree.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/test_paths.h"

namespace sagrid {
namespace {

namespace fs = std::filesystem;
using test::runCommand;
using test::shellQuote;
using ::testing::HasSubstr;

fs::path buildPackage(const fs::path& dir) {
  const fs::path buildDir = test::sagridBinary().parent_path();
  const auto packed =
      runCommand("cpack -G DEB --config " + shellQuote((buildDir / "CPackConfig.cmake").string()) +
                 " -B " + shellQuote(dir.string()));
  EXPECT_EQ(packed.exitCode, 0) << packed.output;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".deb") return e.path();
  }
  ADD_FAILURE() << "no .deb in " << dir << "\n" << packed.output;
  return {};
}

TEST(DebianPackageSlow, ContentsDependenciesAndAnnotateFromAnExtractedRoot) {
  const fs::path dir = test::freshTempDir();
  const fs::path deb = buildPackage(dir / "pkg");
  ASSERT_FALSE(deb.empty());
  std::string arch = runCommand("dpkg --print-architecture").output;
  arch.erase(arch.find_last_not_of("\n") + 1);
  EXPECT_EQ(deb.filename().string(), "sagrid_" SAGRID_VERSION "_" + arch + ".deb");

  const auto contents = runCommand("dpkg-deb -c " + shellQuote(deb.string()));
  ASSERT_EQ(contents.exitCode, 0) << contents.output;
  for (const char* file :
       {"./usr/bin/sagrid", "./usr/share/sagrid/models/stove.heatsource.pt",
        "./usr/share/sagrid/models/stove.heatsource.json",
        "./usr/share/sagrid/models/sink.fluidsource.pt", "./usr/share/sagrid/models/category.json",
        "./usr/share/sagrid/models/units_memory.json",
        "./usr/share/sagrid/samples/stove_s42_00001/mesh.obj",
        "./usr/share/sagrid/samples/sink_s42_00001/mesh.glb",
        "./usr/share/applications/sagrid.desktop",
        "./usr/share/icons/hicolor/scalable/apps/sagrid.svg", "./usr/share/man/man1/sagrid.1.gz"}) {
    EXPECT_THAT(contents.output, HasSubstr(std::string(" ") + file + "\n")) << file;
  }
  EXPECT_THAT(contents.output, ::testing::Not(HasSubstr(".loss.csv")));

  // dpkg-shlibdeps read the libraries off the binary.
  const auto depends = runCommand("dpkg-deb -f " + shellQuote(deb.string()) + " Depends");
  for (const char* package : {"libtorch", "libassimp", "libembree", "libstdc++6", "libc6"})
    EXPECT_THAT(depends.output, HasSubstr(package)) << depends.output;

  const fs::path root = dir / "root", work = dir / "work";
  fs::create_directories(work);
  ASSERT_EQ(
      runCommand("dpkg -x " + shellQuote(deb.string()) + " " + shellQuote(root.string())).exitCode,
      0);
  const std::string sagrid =
      "cd " + shellQuote(work.string()) + " && " + shellQuote((root / "usr/bin/sagrid").string());

  const auto version = runCommand(sagrid + " --version");
  EXPECT_EQ(version.exitCode, 0) << version.output;
  EXPECT_THAT(version.output, HasSubstr("sagrid " SAGRID_VERSION));

  const auto man =
      runCommand("zcat " + shellQuote((root / "usr/share/man/man1/sagrid.1.gz").string()));
  EXPECT_THAT(man.output, HasSubstr(".SH NAME"));
  EXPECT_THAT(man.output, HasSubstr("sagrid annotate"));  // each command's --help is in the page

  const fs::path sample = root / "usr/share/sagrid/samples/stove_s42_00001/mesh.obj";
  const auto annotated =
      runCommand(sagrid + " annotate " + shellQuote(sample.string()) + " --out out --symmetries 1");
  ASSERT_EQ(annotated.exitCode, 0) << annotated.output;
  std::ifstream labels(work / "out" / "stove_s42_00001" / "labels.json");
  const std::string text((std::istreambuf_iterator<char>(labels)), {});
  EXPECT_THAT(text, HasSubstr("\"heatsource\""));
  EXPECT_THAT(text, HasSubstr("stove.heatsource@"));

  // The models come from the extracted root: with its weights damaged, annotate names them.
  std::ofstream(root / "usr/share/sagrid/models/stove.heatsource.pt", std::ios::trunc) << "damaged";
  const auto damaged = runCommand(sagrid + " annotate " + shellQuote(sample.string()) +
                                  " --out out2 --symmetries 1");
  EXPECT_NE(damaged.exitCode, 0) << damaged.output;
  EXPECT_THAT(damaged.output,
              HasSubstr((root / "usr/share/sagrid/models/stove.heatsource.pt").string()));
}

TEST(DebianPackage, DesktopEntryStartsTheGuiWithTheIcon) {
  std::ifstream file(fs::path(SAGRID_SOURCE_DIR) / "packaging/debian/sagrid.desktop");
  const std::string text((std::istreambuf_iterator<char>(file)), {});
  EXPECT_THAT(text, HasSubstr("[Desktop Entry]\n"));
  EXPECT_THAT(text, HasSubstr("\nExec=sagrid gui %F\n"));
  EXPECT_THAT(text, HasSubstr("\nIcon=sagrid\n"));
  EXPECT_THAT(text, HasSubstr("\nType=Application\n"));
  const auto validated = runCommand(
      "command -v desktop-file-validate > /dev/null || exit 77; "
      "desktop-file-validate " +
      shellQuote(std::string(SAGRID_SOURCE_DIR) + "/packaging/debian/sagrid.desktop"));
  if (validated.exitCode != 77) EXPECT_EQ(validated.exitCode, 0) << validated.output;
}

}  // namespace
}  // namespace sagrid
