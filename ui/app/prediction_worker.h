// Runs SAGrid prediction for the open object on a worker thread, so the UI never blocks: progress
// in [0, 1], a cancel flag the job checks, and the result handed back to the UI thread by poll().
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/labels/labels.h"
#include "core/mesh/unit_guess.h"
#include "ui/document/distance_field.h"

namespace sagrid::ui {

struct PredictionResult {
  std::string category;
  // The category classifier rejected the object (category "none", no points); closestCategory
  // is its best guess for the curator.
  bool rejected = false;
  std::string closestCategory;
  bool rejectedByEvidence = false;  // filed under closestCategory, whose models found too little
  // The words of the file's name that moved the category (AnnotationResult::categoryNameWords).
  std::vector<std::string> categoryNameWords;
  // What the shape alone decided where the name changed it (AnnotationResult); empty otherwise.
  std::string categoryByShapeAlone;
  std::vector<AffordancePoint> points;  // mesh file coordinates, status "predicted"
  double objectConfidence = 0;          // P(right with one key), core/annotate/object_confidence.h
  std::vector<DistanceField> fields;
  std::optional<UnitGuess> units;  // from the mesh's size and the category (core/mesh/unit_guess.h)
  std::optional<std::string> suggestedCategory;  // a rejected object's points are this category's
};

struct PredictionProgress {
  std::atomic<float> fraction{0.0f};
  std::atomic<bool> cancel{false};
};

// A prediction job: reads the progress' cancel flag, writes its fraction, throws sagrid::Cancelled
// when cancelled and sagrid::Error on failure.
using PredictionJob = std::function<PredictionResult(PredictionProgress&)>;

class PredictionWorker {
 public:
  ~PredictionWorker();
  void start(std::string objectKey, PredictionJob job);  // cancels and joins a running job first
  void cancel();
  bool running() const { return m_running.load(); }
  float progress() const { return m_progress ? m_progress->fraction.load() : 0.0f; }
  const std::string& objectKey() const { return m_key; }

  struct Outcome {
    std::string objectKey;
    std::optional<PredictionResult> result;  // empty when it failed or was cancelled
    std::string error;                       // empty on success or cancel
    bool cancelled = false;
  };
  // The finished job's outcome, once; nullopt while running or when nothing finished.
  std::optional<Outcome> poll();

 private:
  void join();
  std::thread m_thread;
  std::shared_ptr<PredictionProgress> m_progress;
  std::atomic<bool> m_running{false};
  std::string m_key;
  std::mutex m_mutex;
  std::optional<Outcome> m_outcome;
};

}  // namespace sagrid::ui
