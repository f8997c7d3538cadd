// Close the loop: retrains the models of one category on the training set the curator fills
// ("Add to training set"), in the background with progress, a live loss curve and cancel; then
// re-runs the new models on the review queue's unreviewed objects and counts how many predicted
// points moved. Reviewed objects are never touched.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ui/document/review_queue.h"

namespace sagrid::ui {

struct TrainingRequest {
  std::filesystem::path dataset;  // dataset layout with manifest.jsonl
  std::string category;
  std::filesystem::path outDir;  // models written here (<category>.<type>.json)
  double minutesPerModel = 1.0;
  int epochs = 0;                   // > 0: fixed epoch count instead of the time budget
  std::vector<QueueEntry> requeue;  // objects to predict again afterwards
  // Fine-tune these models (the ones the GUI loaded) instead of training from scratch, as
  // `sagrid train --init DIR` does; a type without a model there is trained from scratch.
  std::filesystem::path initDir;
  bool replay = true;  // with initDir: the bench split's train half replayed 1:1 beside the set
  // With initDir: each fine-tuned network joins the init model's networks instead of replacing
  // them, as `sagrid train --keep-init` does.
  bool keepInitNetworks = false;
  // With initDir: curated objects of other sources; each fine-tuned model replaces the init one
  // only where it is better there (core/training/guarded_update.h). Empty: unguarded.
  std::filesystem::path heldOut;
  // Instead of point models: retrain the category classifier of initDir (else outDir) with the
  // training set's objects and their curated categories (core/annotate/category_update.h), guarded
  // by heldOut when given, else leaving each source of the training set out (unguarded when it
  // holds one source only); written to outDir when adopted, else to outDir/refused/.
  bool categoryClassifier = false;
  // Instead of point models: retrain the learned point decision of initDir (else outDir) on the
  // training set's curated objects and `generated` objects (core/eval/point_scorer_update.h),
  // guarded by heldOut when given (guardPointScorer: each category's best mix of the loaded and
  // new decisions, judged as a whole, goes into outDir's point_scorer.json), else leaving each
  // source of the training set out (guardPointScorerBySource; unguarded with one source), and the
  // whole new scorer goes to outDir/refused/ where any model's new decision was not taken.
  bool pointScorer = false;
  std::filesystem::path
      generated;  // empty: the bench's val and decision splits (generated when missing)
  // Instead of point models: grow the units memory of initDir (else outDir; none there: a new one)
  // with the training set's objects and their curated units (core/eval/size_memory_update.h),
  // guarded leaving each source out against the named units; written to outDir when adopted,
  // else to outDir/refused/.
  bool unitsMemory = false;
};

struct TrainingStatus {
  bool running = false;
  std::string phase;          // "features", "training stove.heatsource", "predicting", ...
  float fraction = 0;         // of the whole request
  std::vector<float> losses;  // per step report of the model being trained
  std::string finished;       // summary once done
  std::vector<std::string> verdicts;  // the guard's, one line per model
  std::string error;
};

// Affordance types the dataset holds for `category` (from its labels), sorted; throws FileError
// for an unreadable manifest.
std::vector<std::string> trainingTypes(const std::filesystem::path& dataset,
                                       const std::string& category);

// The models folder `out` made whole from `from`: every file it lacks is copied (the GUI predicts
// from `out` after a run, whatever its verdict). Nothing when both are one folder.
void completeModelsFolder(const std::filesystem::path& from, const std::filesystem::path& out);

class TrainingWorker {
 public:
  ~TrainingWorker();
  void start(TrainingRequest request);
  void cancel() { m_cancel = true; }
  bool running() const { return m_running.load(); }
  TrainingStatus status() const;  // a copy, for the panel
  // True once after a run finished successfully (the caller then reloads its models).
  bool takeFinished();

 private:
  void run(TrainingRequest request);
  void runPointModels(const TrainingRequest& request);
  void runCategoryClassifier(const TrainingRequest& request);
  void runPointScorer(const TrainingRequest& request);
  void runUnitsMemory(const TrainingRequest& request);
  // After an adopted update: the queue's unreviewed objects predicted again with the models in
  // request.outDir; the summary's clause.
  std::string predictQueueAgainClause(const TrainingRequest& request);
  struct RequeueCounts {
    std::size_t objects = 0, moved = 0, compared = 0, recategorized = 0;
  };
  // Predicts the unreviewed objects of request.requeue again with the models in request.outDir:
  // as `category` (objects of another category are left), or, empty, in the category the
  // classifier decides. Progress from fractionFrom over fractionSpan.
  RequeueCounts predictQueueAgain(const TrainingRequest& request, const std::string& category,
                                  double fractionFrom, double fractionSpan);
  void update(const std::function<void(TrainingStatus&)>& change);

  std::thread m_thread;
  std::atomic<bool> m_running{false};
  std::atomic<bool> m_cancel{false};
  mutable std::mutex m_mutex;
  TrainingStatus m_status;
  bool m_finishedFlag = false;
};

}  // namespace sagrid::ui
