#include "ui/app/prediction_worker.h"

#include <utility>

#include "core/common/error.h"

namespace sagrid::ui {

PredictionWorker::~PredictionWorker() {
  cancel();
  join();
}

void PredictionWorker::join() {
  if (m_thread.joinable()) m_thread.join();
}

void PredictionWorker::cancel() {
  if (m_progress) m_progress->cancel = true;
}

void PredictionWorker::start(std::string objectKey, PredictionJob job) {
  cancel();
  join();
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_outcome.reset();
  }
  m_key = objectKey;
  m_progress = std::make_shared<PredictionProgress>();
  m_running = true;
  m_thread =
      std::thread([this, key = std::move(objectKey), job = std::move(job), progress = m_progress] {
        Outcome outcome;
        outcome.objectKey = key;
        try {
          outcome.result = job(*progress);
        } catch (const Cancelled&) {
          outcome.cancelled = true;
        } catch (const std::exception& e) {
          outcome.error = e.what();
        }
        std::lock_guard<std::mutex> lock(m_mutex);
        m_outcome = std::move(outcome);
        m_running = false;
      });
}

std::optional<PredictionWorker::Outcome> PredictionWorker::poll() {
  std::lock_guard<std::mutex> lock(m_mutex);
  if (!m_outcome) return std::nullopt;
  auto outcome = std::move(m_outcome);
  m_outcome.reset();
  return outcome;
}

}  // namespace sagrid::ui
