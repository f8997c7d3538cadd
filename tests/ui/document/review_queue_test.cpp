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

TEST(ReviewQueue, AnObjectInProgressIsKeptButNotCountedAsReviewed) {
  const auto dir = test::freshTempDir();
  for (const char* id : {"o1", "o2"}) touch(dir / id / "mesh.obj");
  {
    ReviewQueue queue = ReviewQueue::openFolder(dir);
    queue.setState(0, QueueState::InProgress);
    queue.setState(1, QueueState::Skipped);
    EXPECT_EQ(queue.reviewedCount(), 1u);
  }
  const ReviewQueue resumed = ReviewQueue::openFolder(dir);
  EXPECT_EQ(resumed.entry(0).state, QueueState::InProgress);
  EXPECT_EQ(std::string(toString(QueueState::InProgress)), "in progress");
  EXPECT_EQ(resumed.reviewedCount(), 1u);
}

GeometryOutline outline(std::size_t triangles, Eigen::Vector3d size) {
  GeometryOutline o;
  o.triangles = triangles;
  o.size = size;
  return o;
}

TEST(ReviewQueue, KeepsGeometryAndFindsOnlyCuratedCandidatesOfTheSameOutline) {
  const auto dir = test::freshTempDir();
  for (const char* id : {"o1", "o2", "o3", "o4", "o5", "o6"}) touch(dir / id / "mesh.obj");
  const Eigen::Vector3d size(101.2, 48.7, 60.05);
  const GeometryOutline basin = outline(6636, size);
  // Elsewhere in its file, its size 1e-4 units (1e-6 of it) off: a file printing 4 decimals.
  const GeometryOutline basinElsewhere =
      outline(6636, size + Eigen::Vector3d(1e-4, -1e-4, 0));
  const GeometryOutline longer = outline(6636, size + Eigen::Vector3d(0.1, 0, 0));
  const GeometryOutline fewer = outline(6634, size);
  {
    ReviewQueue queue = ReviewQueue::openFolder(dir);
    queue.setGeometry(0, basin);
    queue.setGeometry(1, basinElsewhere);
    queue.setGeometry(2, longer);
    queue.setGeometry(3, basin);
    queue.setGeometry(4, fewer);
    for (std::size_t i : {1, 2, 4}) queue.setState(i, QueueState::Edited);
    queue.setState(3, QueueState::Skipped);  // seen, not curated
    EXPECT_EQ(queue.curatedTwinCandidatesOf(0), std::vector<std::size_t>{1});
    EXPECT_TRUE(queue.curatedTwinCandidatesOf(5).empty());  // never opened: no geometry yet
  }
  const ReviewQueue resumed = ReviewQueue::openFolder(dir);
  ASSERT_TRUE(resumed.entry(1).geometry);
  EXPECT_EQ(*resumed.entry(1).geometry, basinElsewhere);  // the numbers as they were
  EXPECT_FALSE(resumed.entry(5).geometry);
  EXPECT_EQ(resumed.curatedTwinCandidatesOf(0), std::vector<std::size_t>{1});
  EXPECT_EQ(resumed.curatedTwinCandidatesOf(3), std::vector<std::size_t>{1});
  EXPECT_TRUE(resumed.curatedTwinCandidatesOf(1).empty());  // its twins are not curated
}

TEST(ReviewQueue, AGeometryWithoutItsNumbersIsForgottenAndTheStateKept) {
  // A geometry without a triangle count and box size (damaged, or not this build's) finds no twin.
  const auto dir = test::freshTempDir();
  for (const char* id : {"o1", "o2"}) touch(dir / id / "mesh.obj");
  std::ofstream(dir / kQueueStateFile) << R"({"schema": "sagrid.review-queue/1", "objects": [
    {"mesh": "o1/mesh.obj", "state": "edited",
     "geometry": {"shape": "aa", "triangle_order": "01", "origin": [1, 2, 3]}},
    {"mesh": "o2/mesh.obj", "state": "unreviewed",
     "geometry": {"triangles": 12, "origin": [1, 2, 3], "size": [0.5, 0.25, 1]}}]})";
  const ReviewQueue queue = ReviewQueue::openFolder(dir);
  EXPECT_EQ(queue.entry(0).state, QueueState::Edited);
  EXPECT_FALSE(queue.entry(0).geometry);
  ASSERT_TRUE(queue.entry(1).geometry);
  EXPECT_EQ(*queue.entry(1).geometry, outline(12, {0.5, 0.25, 1}));
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

TEST(ReviewQueue, OrdersLeastSureFirstAndFindsAutoAcceptCandidates) {
  const auto dir = test::freshTempDir();
  const std::pair<const char*, const char*> objects[] = {
      {"o1", R"({"prediction": {"object_confidence": 0.95}})"},
      {"o2", R"({"prediction": {"object_confidence": 0.20}})"},
      {"o3", nullptr},                            // not predicted yet
      {"o4", R"({"prediction": {"object_confidence": "high"}})"},  // not a number: none
      {"o5", R"({"prediction": {"object_confidence": 0.90}})"}};
  for (const auto& [id, labels] : objects) {
    touch(dir / id / "mesh.obj");
    if (labels) std::ofstream(dir / id / "labels.json") << labels;
  }
  ReviewQueue queue = ReviewQueue::openFolder(dir);
  ASSERT_EQ(queue.size(), 5u);
  EXPECT_DOUBLE_EQ(queue.entry(0).confidence.value(), 0.95);
  EXPECT_FALSE(queue.entry(2).confidence.has_value());
  EXPECT_FALSE(queue.entry(3).confidence.has_value());
  queue.setCurrent(4);  // o5
  queue.setState(0, QueueState::Edited);  // o1 reviewed already
  EXPECT_EQ(queue.unreviewedAtOrAbove(0.9), std::vector<std::size_t>{4});
  queue.orderLeastSureFirst();
  std::vector<std::string> order;
  for (const auto& e : queue.entries()) order.push_back(e.mesh.parent_path().filename().string());
  EXPECT_EQ(order, (std::vector<std::string>{"o3", "o4", "o2", "o5", "o1"}));
  EXPECT_EQ(queue.current(), 3);  // still o5
  queue.setConfidence(0, 0.99);   // o3 predicted now
  EXPECT_EQ(queue.unreviewedAtOrAbove(0.9), (std::vector<std::size_t>{0, 3}));
}

}  // namespace
}  // namespace sagrid::ui
