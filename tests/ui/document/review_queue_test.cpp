// The review queue over a folder: finds objects in the dataset layout and loose meshes, keeps
// states and position in DIR/.sagrid-review.json, and resumes from it.
#include "ui/document/review_queue.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/test_paths.h"

namespace sagrid::ui {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& path) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << "v 0 0 0\n";
}

TEST(ReviewQueue, FindsObjectFoldersAndLooseMeshesSorted) {
  const auto dir = test::freshTempDir();
  touch(dir / "b" / "mesh.obj");
  touch(dir / "a" / "mesh.glb");
  touch(dir / "loose1.obj");
  touch(dir / "loose2.stl");
  touch(dir / "notes.txt");
  const ReviewQueue queue = ReviewQueue::openFolder(dir);
  ASSERT_EQ(queue.size(), 4u);
  EXPECT_EQ(queue.entry(0).mesh.filename(), "mesh.glb");
  EXPECT_EQ(queue.entry(0).labels, fs::absolute(dir / "a" / "labels.json").lexically_normal());
  EXPECT_EQ(queue.entry(2).labels.filename(),
            "loose1.labels.json");  // two meshes share that folder
  EXPECT_EQ(queue.reviewedCount(), 0u);
}

TEST(ReviewQueue, ResumesStatesAndPosition) {
  const auto dir = test::freshTempDir();
  for (const char* id : {"o1", "o2", "o3"}) touch(dir / id / "mesh.obj");
  {
    ReviewQueue queue = ReviewQueue::openFolder(dir);
    queue.setState(0, QueueState::Accepted);
    queue.setState(1, QueueState::Edited);
    EXPECT_TRUE(queue.next());
    EXPECT_TRUE(queue.next());
    EXPECT_FALSE(queue.next());
  }
  ASSERT_TRUE(fs::exists(dir / kQueueStateFile));
  const ReviewQueue resumed = ReviewQueue::openFolder(dir);
  EXPECT_EQ(resumed.current(), 2);
  EXPECT_EQ(resumed.entry(0).state, QueueState::Accepted);
  EXPECT_EQ(resumed.entry(1).state, QueueState::Edited);
  EXPECT_EQ(resumed.entry(2).state, QueueState::Unreviewed);
  EXPECT_EQ(resumed.reviewedCount(), 2u);
}

TEST(ReviewQueue, DamagedStateFileStartsOver) {
  const auto dir = test::freshTempDir();
  touch(dir / "o1" / "mesh.obj");
  std::ofstream(dir / kQueueStateFile) << "{ not json";
  const ReviewQueue queue = ReviewQueue::openFolder(dir);
  EXPECT_EQ(queue.size(), 1u);
  EXPECT_EQ(queue.current(), 0);
}

TEST(ReviewQueue, AddingPathsInsertsAfterCurrentWithoutDuplicates) {
  const auto dir = test::freshTempDir();
  touch(dir / "o1" / "mesh.obj");
  touch(dir / "o2" / "mesh.obj");
  touch(dir / "extra" / "thing.obj");
  ReviewQueue queue = ReviewQueue::openFolder(dir / "o1");
  EXPECT_EQ(queue.size(), 1u);
  EXPECT_EQ(queue.add({dir / "extra" / "thing.obj"}), 1);
  EXPECT_EQ(queue.add({dir / "extra" / "thing.obj"}), 1);
  EXPECT_EQ(queue.size(), 2u);
}

}  // namespace
}  // namespace sagrid::ui
