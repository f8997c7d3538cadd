// End-to-end: `sagrid info` and `sagrid voxelize` run as a user would, on the real-dev objects
// and on bad input (one line naming the file, exit code != 0, no output file left behind).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/io/npz.h"
#include "core/mesh/mesh_export.h"
#include "support/analytic_meshes.h"
#include "support/import_errors.h"
#include "support/test_paths.h"

namespace sagrid {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::writeFile;
using test::runSagrid;
using test::shellQuote;

const char* kRealDev[] = {"libero__basin_faucet", "libero__faucet_knob", "libero__flat_stove"};

fs::path realDevMesh(const char* name) { return test::realDevDir() / name / "mesh.obj"; }

TEST(InfoCommand, RealDevObjects) {
  if (!fs::exists(test::realDevDir())) GTEST_SKIP();
  for (const char* name : kRealDev) {
    const auto r = runSagrid("info " + shellQuote(realDevMesh(name).string()));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_THAT(r.output, HasSubstr("triangles:"));
    EXPECT_THAT(r.output, HasSubstr("bounds min:"));
    EXPECT_THAT(r.output, HasSubstr("normalize:"));
    EXPECT_THAT(r.output, HasSubstr("of 64^3 voxels"));
    EXPECT_THAT(r.output, HasSubstr("time voxelize:"));
  }
}

TEST(InfoCommand, JsonReportAgreesWithVoxelizeOutput) {
  if (!fs::exists(test::realDevDir())) GTEST_SKIP();
  const fs::path mesh = realDevMesh("libero__flat_stove");
  const auto r = runSagrid("info " + shellQuote(mesh.string()) + " --json --resolution 32");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto report = nlohmann::json::parse(r.output);
  EXPECT_GT(report["triangles"].get<int>(), 1000);
  EXPECT_EQ(report["resolution"], 32);
  EXPECT_EQ(report["file_up"], "z");
  const double size = report["bounds"]["max"][0].get<double>() - report["bounds"]["min"][0].get<double>();
  EXPECT_NEAR(report["normalization"]["scale"].get<double>(), 1.0 / size, 1e-4);  // x is largest
  EXPECT_TRUE(report["time_ms"].contains("voxelize"));

  const fs::path out = test::freshTempDir() / "stove.npz";
  const auto v = runSagrid("voxelize " + shellQuote(mesh.string()) + " --resolution 32 --out " + shellQuote(out.string()));
  ASSERT_EQ(v.exitCode, 0) << v.output;
  const NpzArchive archive = readNpz(out);
  const NpyArray& coords = archive.at("coords");
  EXPECT_EQ(coords.dtype, "uint8");
  ASSERT_EQ(coords.shape.size(), 2u);
  EXPECT_EQ(coords.shape[1], 3u);
  EXPECT_EQ(coords.shape[0], report["occupied_voxels"].get<std::size_t>());
  EXPECT_EQ(archive.at("resolution").as<std::int64_t>()[0], 32);
  for (std::uint8_t c : coords.as<std::uint8_t>()) EXPECT_LT(c, 32);
}

TEST(VoxelizeCommand, PlyPointsAtVoxelCentres) {
  if (!fs::exists(test::realDevDir())) GTEST_SKIP();
  const fs::path out = test::freshTempDir() / "knob.ply";
  const auto r = runSagrid("voxelize " + shellQuote(realDevMesh("libero__faucet_knob").string()) +
                           " --resolution 16 --out " + shellQuote(out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(out);
  std::string line;
  std::size_t declared = 0, points = 0;
  bool body = false;
  while (std::getline(in, line)) {
    if (line.rfind("element vertex ", 0) == 0) declared = std::stoul(line.substr(15));
    if (body) {
      float x, y, z;
      ASSERT_EQ(std::sscanf(line.c_str(), "%f %f %f", &x, &y, &z), 3);
      for (float c : {x, y, z}) {
        EXPECT_LT(std::abs(c), 0.5f);
        const float cell = (c + 0.5f) * 16 - 0.5f;  // integer at a voxel centre
        EXPECT_NEAR(cell, std::round(cell), 1e-4f);
      }
      ++points;
    }
    if (line == "end_header") body = true;
  }
  EXPECT_GT(points, 50u);
  EXPECT_EQ(points, declared);
}

// ---- bad input

void expectOneLineError(const fs::path& mesh, const std::string& problem) {
  SCOPED_TRACE(mesh.string());
  const fs::path outDir = test::freshTempDir("out");
  const fs::path out = outDir / "voxels.npz";
  // voxelize is the command that writes; `info` shares the import path (checked once below).
  const auto r = runSagrid("voxelize " + shellQuote(mesh.string()) + " --out " + shellQuote(out.string()));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("sagrid: error: " + mesh.string() + ": "));
  EXPECT_THAT(r.output, HasSubstr(problem));
  EXPECT_TRUE(fs::is_empty(outDir)) << "no output or temporary file left behind";
}

TEST(GeometryCliErrors, UnreadableFilesGiveOneLineNamingTheFile) {
  const fs::path dir = test::freshTempDir();
  const auto info = runSagrid("info " + shellQuote((dir / "missing.obj").string()));
  EXPECT_EQ(info.exitCode, 1);
  EXPECT_EQ(info.output, "sagrid: error: " + (dir / "missing.obj").string() + ": file not found\n");
  expectOneLineError(dir / "missing.obj", "file not found");
  fs::create_directory(dir / "folder.glb");
  expectOneLineError(dir / "folder.glb", "is a directory");
  expectOneLineError(writeFile(dir / "mesh.3ds", "x"), "unsupported mesh format");
  expectOneLineError(writeFile(dir / "zero.glb", ""), "is empty (0 bytes)");
}

TEST(GeometryCliErrors, BadGeometryGivesOneLineNamingTheFile) {
  const fs::path dir = test::freshTempDir();
  expectOneLineError(writeFile(dir / "truncated.glb", std::string("glTF\x02\0\0\0\xff\0\0\0", 12) + "{\"asset\""),
                     "declares 255 bytes but the file has 20 (truncated?)");
  std::string nanStl(80, ' ');
  const std::uint32_t count = 1;
  const float facet[12] = {0, 0, 1, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0, 0, 1, 0};
  nanStl.append(reinterpret_cast<const char*>(&count), 4).append(reinterpret_cast<const char*>(facet), 48).append(2, '\0');
  expectOneLineError(writeFile(dir / "nan.stl", nanStl), "NaN or infinite");
  expectOneLineError(writeFile(dir / "degenerate.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n"),
                     "only degenerate triangles");
  expectOneLineError(writeFile(dir / "empty.obj", "# no geometry\nv 0 0 0\n"), "no triangles");
  expectOneLineError(writeFile(dir / "far.obj", "v 1e9 0 0\nv 1e9 0.5 0\nv 1e9 0 0.5\nf 1 2 3\n"), "too small");
}

TEST(GeometryCliErrors, BadOutputPathFailsBeforeWork) {
  const fs::path dir = test::freshTempDir();
  const fs::path mesh = writeFile(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  auto r = runSagrid("voxelize " + shellQuote(mesh.string()) + " --out " + shellQuote((dir / "v.txt").string()));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_THAT(r.output, HasSubstr("unsupported output format '.txt'"));
  r = runSagrid("voxelize " + shellQuote(mesh.string()) + " --out " + shellQuote((dir / "no" / "v.npz").string()));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_THAT(r.output, HasSubstr("does not exist"));
  EXPECT_FALSE(fs::exists(dir / "no"));
  r = runSagrid("voxelize " + shellQuote(mesh.string()) + " --out " + shellQuote((dir / "v.npz").string()));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "v.npz"));
}

TEST(GeometryCli, HelpAndUpOption) {
  EXPECT_EQ(runSagrid("info --help").exitCode, 0);
  EXPECT_THAT(runSagrid("voxelize --help").output, HasSubstr("--resolution"));
  const fs::path dir = test::freshTempDir();
  const fs::path mesh = writeFile(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 2 0\nf 1 2 3\n");
  const auto r = runSagrid("info " + shellQuote(mesh.string()) + " --up y --json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto report = nlohmann::json::parse(r.output);
  EXPECT_EQ(report["file_up"], "y");
  EXPECT_NEAR(report["bounds"]["max"][2].get<double>(), 2.0, 1e-6);  // file y became z
  EXPECT_NE(runSagrid("info " + shellQuote(mesh.string()) + " --up w").exitCode, 0);
}

TEST(InfoCommand, PrintsTheUnitsAnnotateWouldGuess) {
  // A stove 90 units tall is in centimetres.
  const fs::path dir = test::freshTempDir();
  exportMesh(test::box({0, 0, 0}, {60, 60, 90}), dir / "stove.obj");
  const std::string info = "info " + shellQuote((dir / "stove.obj").string()) + " --up z";
  auto r = runSagrid(info + " --units-for stove");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("units guess: cm, 0.01 m per unit (largest extent 90 units"));
  r = runSagrid(info + " --units-for stove --json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(nlohmann::json::parse(r.output).at("units_guess").at("unit"), "cm");
}

TEST(InfoCommand, SameGeometryAsSaysWhetherTwoFilesHoldTheSameTrianglesAndTheirOffset) {
  const fs::path dir = test::freshTempDir();
  const Mesh stove = test::box({0, 0, 0}, {0.6f, 0.6f, 0.9f});
  exportMesh(stove, dir / "stove.obj");
  Mesh red = stove;  // another material, the triangles listed backwards
  red.materials = {{"red", {1, 0, 0}, -1}};
  red.triangleMaterials.assign(red.triangles.size(), 0);
  std::reverse(red.triangles.begin(), red.triangles.end());
  exportMesh(red, dir / "red.obj");
  exportMesh(test::box({0, 0, 0}, {0.6f, 0.6f, 0.95f}), dir / "taller.obj");
  exportMesh(test::box({2, -1, 0.5f}, {2.6f, -0.4f, 1.4f}), dir / "moved.obj");
  auto sameAs = [&](const char* file, const char* other) {
    const auto r = runSagrid("info " + shellQuote((dir / file).string()) +
                             " --json --same-geometry-as " + shellQuote((dir / other).string()));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return nlohmann::json::parse(r.output).at("same_geometry");
  };
  const auto red_ = sameAs("red.obj", "stove.obj");
  EXPECT_TRUE(red_.at("same").get<bool>());
  EXPECT_FALSE(red_.at("same_triangle_order").get<bool>());
  EXPECT_FALSE(sameAs("taller.obj", "stove.obj").at("same").get<bool>());
  EXPECT_TRUE(sameAs("taller.obj", "stove.obj").at("offset").is_null());
  const auto moved = sameAs("moved.obj", "stove.obj");  // elsewhere in its file
  ASSERT_TRUE(moved.at("same").get<bool>());
  EXPECT_TRUE(moved.at("same_triangle_order").get<bool>());
  const auto offset = moved.at("offset");
  EXPECT_NEAR(offset.at(0).get<double>(), 2.0, 1e-6);
  EXPECT_NEAR(offset.at(1).get<double>(), -1.0, 1e-6);
  EXPECT_NEAR(offset.at(2).get<double>(), 0.5, 1e-6);
  const std::string info =
      "info " + shellQuote((dir / "moved.obj").string()) + " --same-geometry-as ";
  EXPECT_THAT(runSagrid(info + shellQuote((dir / "stove.obj").string())).output,
              HasSubstr("stove.obj: yes, offset 2 -1 0.5 (same triangle order)"));
  EXPECT_THAT(runSagrid(info + shellQuote((dir / "taller.obj").string())).output,
              HasSubstr("taller.obj: no"));
}

TEST(InfoCommand, ListsSmallParts) {
  // A cooktop (60 x 40 x 20 cm, z up) with two flat pads on its top and a knob on its front.
  Mesh cooktop = test::box({-0.3f, -0.2f, 0.0f}, {0.3f, 0.2f, 0.2f});
  for (float x : {-0.1f, 0.1f})
    test::append(cooktop, test::box({x - 0.01f, 0.0f, 0.2f}, {x + 0.01f, 0.016f, 0.202f}));
  test::append(cooktop, test::box({0.2f, -0.23f, 0.08f}, {0.24f, -0.2f, 0.12f}));
  const fs::path dir = test::freshTempDir();
  exportMesh(cooktop, dir / "cooktop.obj");
  const auto r = runSagrid("info " + shellQuote((dir / "cooktop.obj").string()) +
                           " --up z --parts");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("small parts: 3 of 4"));
  EXPECT_THAT(r.output, HasSubstr("12 triangles, box centre (0.22, -0.215, 0.1), size (0.04, 0.03, "
                                  "0.04) z-up, 0 copies"));
  EXPECT_THAT(r.output, HasSubstr("part 1: 12 triangles, box centre (-0.1, 0.008, 0.201), size "
                                  "(0.02, 0.016, 0.002"));
  EXPECT_THAT(r.output, HasSubstr("z-up, 1 copies\n  part 2"));
  EXPECT_THAT(r.output, Not(HasSubstr("crease patch")));
  // As a stove model's candidates see them: each box's faces are crease patches too.
  const auto withPatches = runSagrid("info " + shellQuote((dir / "cooktop.obj").string()) +
                                     " --up z --parts --crease-patches");
  ASSERT_EQ(withPatches.exitCode, 0) << withPatches.output;
  EXPECT_THAT(withPatches.output, HasSubstr("part 1: 12 triangles, box centre (-0.1, 0.008, 0.201)"));
  EXPECT_THAT(withPatches.output, HasSubstr("small parts: 21 of 28"));  // 18 faces of 3 boxes
  EXPECT_THAT(withPatches.output, HasSubstr("2 triangles, box centre (0.22, -0.215, 0.12), size "
                                            "(0.04, 0.03, 0) z-up, 0 copies (crease patch)\n"));
}

}  // namespace
}  // namespace sagrid
