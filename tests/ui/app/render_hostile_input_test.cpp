// Issue 14, `sagrid render` on hostile input: an OBJ with 1e30 coordinates or labels at -1e308
// crashed the viewport overlay (SIGSEGV in ImGui's drawing), meters_per_unit 1e308 hit an ImGui
// slider assertion (abort), 200,000 points took minutes and gigabytes, labels nested a million
// deep overflowed the stack. Now each is refused naming the file, and the overlay itself skips
// points it cannot place.
#include <sys/stat.h>

#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/test_paths.h"
#include "tests/ui/app/scripted_scene.h"
#include "ui/document/point_commands.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;
using ::testing::HasSubstr;
using sagrid::test::shellQuote;

const fs::path kBad = fs::path(SAGRID_TEST_DATA_DIR) / "bad";

// `sagrid render` of `mesh` with `labels`; expects exit 1 and one error line naming `named`.
void expectRenderRefuses(const fs::path& mesh, const fs::path& labels, const fs::path& named,
                         const std::string& problem) {
  const fs::path png = mesh.parent_path() / "out.png";
  const auto r = sagrid::test::runCommand(
      "timeout 60 " + shellQuote(sagrid::test::sagridBinary().string()) + " render " +
      shellQuote(mesh.string()) + " --labels " + shellQuote(labels.string()) +
      " --backend egl --size 320x240 --screenshot " + shellQuote(png.string()));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(r.output.rfind("sagrid: error: " + named.string() + ": ", 0), 0u) << r.output;
  EXPECT_THAT(r.output, HasSubstr(problem));
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(fs::exists(png));
}

TEST(RenderHostileInput, DamagedLabelsAndMeshesAreRefusedNamingTheFile) {
  const fs::path dir = sagrid::test::freshTempDir();
  test::writeSceneObj(dir / "mesh.obj");
  const std::pair<const char*, const char*> labels[] = {
      {"labels_position_minus_1e308.json", "field 'affordances[0].position' holds -1e+308"},
      {"labels_position_1e39.json", "field 'affordances[0].position' holds 1e+39"},
      {"labels_meters_per_unit_1e308.json", "field 'object.meters_per_unit' is 1e+308"},
      {"labels_number_overflow.json", "number overflow"}};
  for (const auto& [name, problem] : labels)
    expectRenderRefuses(dir / "mesh.obj", kBad / name, kBad / name, problem);
  test::writeSceneLabels(dir / "labels.json");
  expectRenderRefuses(kBad / "coordinates_1e30.obj", dir / "labels.json",
                      kBad / "coordinates_1e30.obj", "coordinates must be within");

  nlohmann::json many = nlohmann::json::parse(std::ifstream(dir / "labels.json"));
  const nlohmann::json point = many["affordances"][0];
  for (int i = 0; i < 200000; ++i) many["affordances"].push_back(point);
  std::ofstream(dir / "many.json") << many.dump();
  expectRenderRefuses(dir / "mesh.obj", dir / "many.json", dir / "many.json",
                      "at most 1000 per object");

  std::ofstream(dir / "deep.json") << "{\"x\":" << std::string(1000000, '[')
                                   << std::string(1000000, ']') << "}";
  expectRenderRefuses(dir / "mesh.obj", dir / "deep.json", dir / "deep.json",
                      "more than 64 levels deep");

  ASSERT_EQ(::mkfifo((dir / "fifo.json").c_str(), 0600), 0);
  expectRenderRefuses(dir / "mesh.obj", dir / "fifo.json", dir / "fifo.json", "is a FIFO");
}

// Points placed in code (not read from a file) far off or at infinity: the overlay skips them.
TEST(RenderHostileInput, OverlaySkipsPointsItCannotPlace) {
  const fs::path dir = sagrid::test::freshTempDir();
  test::ScriptedApp s(dir, 320, 240);
  Session& session = s.app->session();
  session.readOnly = true;
  session.view().showPanels = true;
  session.view().field.visible = true;
  AnnotationDocument* doc = session.document();
  ASSERT_NE(doc, nullptr);
  doc->execute(std::make_unique<MovePointCommand>(0, Eigen::Vector3f(-1e30f, 1e30f, 0), std::nullopt));
  doc->execute(std::make_unique<MovePointCommand>(
      1, Eigen::Vector3f(std::numeric_limits<float>::infinity(), 0, 0), std::nullopt));
  s.frame({});
  s.frame({});
  Eigen::Vector2f pixel;
  EXPECT_FALSE(session.camera().project(Eigen::Vector3f(NAN, 0, 0), pixel));
  EXPECT_EQ(s.app->capture().width, 320);
}

}  // namespace
}  // namespace sagrid::ui
