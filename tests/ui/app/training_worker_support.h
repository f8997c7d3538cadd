// For the Train panel's worker tests: a request run to its end, and a review queue to predict
// again.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core/labels/labels.h"
#include "ui/app/training_worker.h"

namespace sagrid::test {

// A request over the folders the worker tests lay out in `dir`: the curator's training set
// dir/curated, the loaded models dir/loaded, the models written to dir/out.
inline ui::TrainingRequest requestIn(const std::filesystem::path& dir) {
  ui::TrainingRequest request;
  request.dataset = dir / "curated";
  request.outDir = dir / "out";
  request.initDir = dir / "loaded";
  return request;
}

// The status once the worker stopped (a failure is recorded when it did not within `seconds`, or
// when "finished" disagrees with the error).
inline ui::TrainingStatus runToEnd(ui::TrainingRequest request, int seconds) {
  ui::TrainingWorker worker;
  worker.start(std::move(request));
  for (int i = 0; i < 20 * seconds && worker.running(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(worker.running()) << "the request did not finish in " << seconds << " s";
  EXPECT_EQ(worker.takeFinished(), worker.status().error.empty());
  return worker.status();
}

// A review queue in `dir`/queue: an unreviewed object and one the curator accepted, both the
// mesh `mesh` labelled `category` with no points; their labels files are written.
inline std::vector<ui::QueueEntry> reviewQueue(const std::filesystem::path& dir,
                                               const std::filesystem::path& mesh,
                                               const std::string& category) {
  std::vector<ui::QueueEntry> queue;
  for (ui::QueueState state : {ui::QueueState::Unreviewed, ui::QueueState::Accepted}) {
    const std::filesystem::path labels = dir / "queue" / toString(state) / "labels.json";
    std::filesystem::create_directories(labels.parent_path());
    ObjectLabels l;
    l.object.id = toString(state);
    l.object.category = category;
    writeLabels(labels, l);
    queue.push_back({mesh, labels, state, {}, {}, {}});
  }
  return queue;
}

}  // namespace sagrid::test
