// The window's predictions read the mesh file's name as the Object panel's checkbox says
// (Session::categoryReadsFileName): the shipped models predict copies of one shape named for each
// class; reading names, some copy is filed or rejected by its name against its shape and the note
// says so; not reading them, every copy takes its shape's category and no note names the file.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "support/test_paths.h"
#include "tests/ui/app/scripted_scene.h"

namespace sagrid::ui {
namespace {

namespace fs = std::filesystem;

// The open object's category and note after "Run SAGrid" on a copy of `mesh` named `stem` in a
// folder of its own under `under`, its category left to the classifier.
std::pair<std::string, std::string> predicted(test::ScriptedApp& s, const fs::path& mesh,
                                              const fs::path& under, const std::string& stem) {
  const fs::path folder = under / stem;
  fs::create_directories(folder);
  fs::copy_file(mesh, folder / (stem + ".obj"));
  ObjectLabels labels;
  labels.object.id = stem;
  labels.object.mesh = stem + ".obj";
  writeLabels(folder / "labels.json", labels);
  Session& session = s.app->session();
  session.openObject(folder / (stem + ".obj"), folder / "labels.json");
  session.runPrediction();
  for (int i = 0; i < 6000 && session.worker().running(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  session.pollPrediction();
  return {session.document()->labels().object.category, session.predictionNote()};
}

TEST(CategoryFileName, TheCheckboxDecidesWhetherTheWindowReadsTheFilesName) {
  const fs::path dir = sagrid::test::freshTempDir();
  test::ScriptedApp s(dir, 480, 400, fs::path(SAGRID_SOURCE_DIR) / "resources" / "models");
  Session& session = s.app->session();
  EXPECT_TRUE(session.categoryReadsFileName);  // on by default, as annotate
  const std::vector<std::string> names = {"kitchen_stove", "bathroom_sink", "coffee_machine"};
  session.categoryReadsFileName = false;
  std::string byShape;
  for (const auto& name : names) {
    const auto [category, note] = predicted(s, dir / "mesh.obj", dir / "shape", name);
    if (byShape.empty()) byShape = category;
    EXPECT_EQ(category, byShape) << name;  // one shape, one category
    EXPECT_EQ(note.find("file's name"), std::string::npos) << note;
  }
  session.categoryReadsFileName = true;
  int namedAgainstShape = 0;
  for (const auto& name : names) {
    const auto [category, note] = predicted(s, dir / "mesh.obj", dir / "named", name);
    if (category == byShape) continue;
    ++namedAgainstShape;
    EXPECT_NE(note.find("file's name"), std::string::npos) << name << ": " << note;
    EXPECT_NE(note.find("by its shape alone"), std::string::npos) << name << ": " << note;
  }
  EXPECT_GE(namedAgainstShape, 1);
}

}  // namespace
}  // namespace sagrid::ui
