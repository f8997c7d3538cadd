// Issue 14, kill -9 safety of the GUI's edit session: a scripted session (moves, adds, deletes and
// undos through the annotation document, autosaving labels.json after each) is killed at 20
// random moments; labels.json is always the previous or the next complete state, never partial,
// and reopening it to edit on completes and leaves no temporary file.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <random>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh.h"
#include "support/analytic_meshes.h"
#include "support/output_check.h"
#include "support/test_paths.h"
#include "ui/document/annotation_document.h"
#include "ui/document/point_commands.h"

namespace sagrid::ui {
namespace {
namespace fs = std::filesystem;

constexpr int kPoints = 300;  // ~60 KB of labels.json: each save takes a while to write

std::shared_ptr<const Mesh> plate() {
  return std::make_shared<Mesh>(test::quadZ({-0.5f, -0.5f}, {0.5f, 0.5f}, 0.0f));
}

AffordancePoint pointAt(float x, float y) {
  AffordancePoint p;
  p.type = "heatsource";
  p.position = {x, y, 0.0f};
  p.source = "human";
  return p;
}

ObjectLabels manyPoints() {
  ObjectLabels labels;
  labels.object.id = "plate";
  labels.object.mesh = "mesh.obj";
  labels.object.category = "stove";
  for (int i = 0; i < kPoints; ++i) labels.affordances.push_back(pointAt(0.001f * i, -0.001f * i));
  return labels;
}

// The scripted session: edits forever, each one autosaved; only a kill ends it.
void editForever(const fs::path& labelsPath) {
  AnnotationDocument doc(plate(), readLabels(labelsPath), labelsPath);
  std::mt19937 random(::getpid());
  std::uniform_real_distribution<float> coordinate(-0.5f, 0.5f);
  for (int step = 0;; ++step) {
    switch (step % 4) {
      case 0:
        doc.execute(std::make_unique<MovePointCommand>(
            step % static_cast<int>(doc.points().size()), Eigen::Vector3f(coordinate(random), coordinate(random), 0), std::nullopt));
        break;
      case 1: doc.execute(std::make_unique<AddPointCommand>(pointAt(0.25f, 0.25f))); break;
      case 2: doc.undo(); break;
      default:
        doc.execute(std::make_unique<DeletePointCommand>(0));
        doc.undo();
        break;
    }
  }
}

// labels.json must be a state the session wrote: the session's edits keep the point count within
// one of where it started, every point on the plate. Returns the count.
std::size_t expectCompleteState(const fs::path& labelsPath, std::size_t startCount, int kill) {
  ObjectLabels labels;
  try {
    labels = readLabels(labelsPath);
  } catch (const Error& e) {
    ADD_FAILURE() << "after kill " << kill << ": " << e.what();
    return startCount;
  }
  const std::size_t n = labels.affordances.size();
  EXPECT_TRUE(n + 1 >= startCount && n <= startCount + 1) << n << " after kill " << kill;
  for (const auto& p : labels.affordances)
    EXPECT_LE(p.position.cwiseAbs().maxCoeff(), 0.5f) << "after kill " << kill;
  return n;
}

TEST(DocumentKillSafety, AutosaveKilledAtRandomMoments) {
  const fs::path dir = test::freshTempDir();
  const fs::path labelsPath = dir / "labels.json";
  writeLabels(labelsPath, manyPoints());
  std::mt19937 random(14);
  std::uniform_int_distribution<int> moment(20, 300);
  std::size_t count = kPoints;
  for (int kill = 0; kill < 20; ++kill) {
    const pid_t pid = ::fork();
    if (pid == 0) {  // the child never returns into the test framework
      try {
        editForever(labelsPath);
      } catch (...) {
      }
      ::_exit(2);
    }
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(moment(random)));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the session ended by itself";
    count = expectCompleteState(labelsPath, count, kill);
  }
  // Reopen and edit on, as the GUI does after a crash.
  AnnotationDocument doc(plate(), readLabels(labelsPath), labelsPath);
  doc.execute(std::make_unique<MovePointCommand>(0, Eigen::Vector3f(0.1f, 0.1f, 0), std::nullopt));
  expectCompleteState(labelsPath, count, 20);
  EXPECT_TRUE(readLabels(labelsPath).affordances[0].position.isApprox(Eigen::Vector3f(0.1f, 0.1f, 0)));
  EXPECT_THAT(test::temporaryFiles(dir), ::testing::IsEmpty());
  EXPECT_EQ(test::relativeFiles(dir), std::vector<std::string>{"labels.json"});
}

}  // namespace
}  // namespace sagrid::ui
