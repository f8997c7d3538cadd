// Close the loop, headless and without GL: train the category's models on a small generated
// training set in the background, then predict the unreviewed queue objects again and report how
// many predicted points moved. Slow (feature extraction + two short trainings).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core/labels/labels.h"
#include "support/test_paths.h"
#include "ui/app/training_worker.h"

namespace sagrid::ui {
namespace {

namespace fs = std::filesystem;

TEST(TrainLoop, TrainThenRepredictQueueSlow) {
  const auto dir = sagrid::test::freshTempDir();
  ASSERT_EQ(sagrid::test::runSagrid("generate --category stove --count 4 --seed 3 --out " +
                                    sagrid::test::shellQuote((dir / "train").string()))
                .exitCode,
            0);
  ASSERT_EQ(sagrid::test::runSagrid("generate --category stove --count 2 --seed 99 --out " +
                                    sagrid::test::shellQuote((dir / "queue").string()))
                .exitCode,
            0);
  EXPECT_EQ(trainingTypes(dir / "train", "stove"),
            (std::vector<std::string>{"heatsource", "togglebutton"}));
  EXPECT_TRUE(trainingTypes(dir / "train", "sink").empty());

  // Queue objects start as stale predictions: one point each, far from anything.
  ReviewQueue queue = ReviewQueue::openFolder(dir / "queue");
  ASSERT_EQ(queue.size(), 2u);
  for (const auto& entry : queue.entries()) {
    ObjectLabels labels = readLabels(entry.labels);
    labels.affordances.resize(1);
    labels.affordances[0].status = AffordanceStatus::Predicted;
    labels.affordances[0].position = {1000, 1000, 1000};
    writeLabels(entry.labels, labels);
  }
  queue.setState(1, QueueState::Accepted);  // reviewed: must not be touched

  TrainingWorker worker;
  TrainingRequest request;
  request.dataset = dir / "train";
  request.category = "stove";
  request.outDir = dir / "models";
  request.epochs = 2;
  request.requeue = queue.entries();
  worker.start(request);
  for (int i = 0; i < 1100 && worker.running(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_FALSE(worker.running()) << "training did not finish in 55 s";
  const TrainingStatus status = worker.status();
  ASSERT_TRUE(status.error.empty()) << status.error;
  EXPECT_TRUE(worker.takeFinished());
  EXPECT_FALSE(status.losses.empty());
  EXPECT_TRUE(fs::exists(dir / "models" / "stove.heatsource.json"));
  EXPECT_TRUE(fs::exists(dir / "models" / "stove.togglebutton.json"));
  EXPECT_NE(status.finished.find("1 of 1 predicted points moved"), std::string::npos)
      << status.finished;
  const ObjectLabels repredicted = readLabels(queue.entry(0).labels);
  ASSERT_FALSE(repredicted.affordances.empty());
  for (const auto& p : repredicted.affordances) {
    EXPECT_EQ(p.status, AffordanceStatus::Predicted);
    EXPECT_GT((p.position - Eigen::Vector3f(1000, 1000, 1000)).norm(),
              1.0f);  // replaced, on the object
  }
  const ObjectLabels reviewed = readLabels(queue.entry(1).labels);
  ASSERT_EQ(reviewed.affordances.size(), 1u);
  EXPECT_FLOAT_EQ(reviewed.affordances[0].position.x(), 1000.0f);
}

}  // namespace
}  // namespace sagrid::ui
