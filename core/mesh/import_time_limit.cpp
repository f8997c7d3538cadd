#include "core/mesh/import_time_limit.h"

#include <assimp/ProgressHandler.hpp>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace sagrid {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

std::mutex g_limitMutex;
ImportTimeLimit g_limit;

std::string secondsText(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", seconds);
  return text;
}

// Assimp calls Update while reading and between post-processing steps; false cancels the import.
class DeadlineProgress : public Assimp::ProgressHandler {
 public:
  explicit DeadlineProgress(Clock::time_point deadline) : m_deadline(deadline) {}
  bool Update(float) override { return Clock::now() < m_deadline; }

 private:
  Clock::time_point m_deadline;
};

}  // namespace

void setImportTimeLimit(const ImportTimeLimit& limit) {
  std::lock_guard<std::mutex> lock(g_limitMutex);
  g_limit = limit;
}

ImportTimeLimit importTimeLimit() {
  std::lock_guard<std::mutex> lock(g_limitMutex);
  return g_limit;
}

ImportDeadline::ImportDeadline(fs::path path, const ImportTimeLimit& limit)
    : m_path(std::move(path)), m_limit(limit) {
  if (m_limit.seconds <= 0) return;
  m_deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                  std::chrono::duration<double>(m_limit.seconds));
  if (m_limit.exitProcess) m_watchdog = std::thread([this] { watch(); });
}

ImportDeadline::~ImportDeadline() {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_done = true;
  }
  m_finished.notify_all();
  if (m_watchdog.joinable()) m_watchdog.join();
}

Assimp::ProgressHandler* ImportDeadline::newProgressHandler() const {
  return m_limit.seconds > 0 ? new DeadlineProgress(m_deadline) : nullptr;
}

bool ImportDeadline::expired() const { return m_limit.seconds > 0 && Clock::now() >= m_deadline; }

std::string ImportDeadline::problem() const {
  return "import did not finish within " + secondsText(m_limit.seconds) +
         " s (--import-time-limit); the file may be malformed or too large";
}

void ImportDeadline::watch() {
  const auto hardStop = m_deadline + std::chrono::duration_cast<Clock::duration>(
                                         std::chrono::duration<double>(m_limit.exitGraceSeconds));
  std::unique_lock<std::mutex> lock(m_mutex);
  if (m_finished.wait_until(lock, hardStop, [this] { return m_done; })) return;
  // The loader ignored the cancel: nothing in this process can stop it. One line, exit 1.
  std::fprintf(stderr, "sagrid: error: %s: %s\n", m_path.string().c_str(), problem().c_str());
  std::fflush(stderr);
  std::_Exit(1);
}

}  // namespace sagrid
