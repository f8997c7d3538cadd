// A one-line progress bar on stderr for batch commands: bar, count, elapsed time and ETA,
// redrawn in place on a terminal and printed as plain lines (at most every few seconds) when
// stderr is a file or pipe, so logs stay readable.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace sagrid::app {

class ProgressBar {
 public:
  ProgressBar(std::string label, std::size_t total);
  ~ProgressBar();  // ends the line

  // `done` items finished; `current` names the item being worked on (shown shortened).
  void update(std::size_t done, const std::string& current = "");
  void finish();
  // A new total (e.g. a time budget re-planning the epoch count); elapsed time carries on.
  void setTotal(std::size_t total) { m_total = total; }

  // "12s", "3m05s", "1h02m" — exposed for tests.
  static std::string formatDuration(double seconds);

 private:
  std::string m_label;
  std::size_t m_total;
  std::chrono::steady_clock::time_point m_start;
  std::chrono::steady_clock::time_point m_lastPrint;
  bool m_tty;
  bool m_finished = false;
};

}  // namespace sagrid::app
