#include "app/progress_bar.h"

#include <unistd.h>

#include <cstdio>

namespace sagrid::app {

ProgressBar::ProgressBar(std::string label, std::size_t total)
    : m_label(std::move(label)),
      m_total(total),
      m_start(std::chrono::steady_clock::now()),
      m_lastPrint(m_start - std::chrono::hours(1)),
      m_tty(isatty(fileno(stderr)) != 0) {}

ProgressBar::~ProgressBar() { finish(); }

std::string ProgressBar::formatDuration(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  if (s < 60) {
    std::snprintf(buf, sizeof buf, "%lds", s);
  } else if (s < 3600) {
    std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  }
  return buf;
}

void ProgressBar::update(std::size_t done, const std::string& current) {
  const auto now = std::chrono::steady_clock::now();
  const bool last = done >= m_total;
  if (!m_tty && !last && now - m_lastPrint < std::chrono::seconds(5)) return;
  if (m_tty && !last && now - m_lastPrint < std::chrono::milliseconds(100)) return;
  m_lastPrint = now;
  const double elapsed = std::chrono::duration<double>(now - m_start).count();
  const double fraction = m_total ? static_cast<double>(done) / m_total : 1.0;
  constexpr int kWidth = 28;
  const int filled = static_cast<int>(fraction * kWidth);
  std::string bar(filled, '=');
  if (filled < kWidth) bar += '>' + std::string(kWidth - filled - 1, ' ');
  std::string eta = "--";
  if (done > 0 && !last) eta = formatDuration(elapsed / done * (m_total - done));
  std::string name = current;
  if (name.size() > 32) name = "..." + name.substr(name.size() - 29);
  std::fprintf(stderr, "%s%s [%s] %zu/%zu  %s elapsed, ETA %s  %s%s", m_tty ? "\r\033[K" : "",
               m_label.c_str(), bar.c_str(), done, m_total, formatDuration(elapsed).c_str(),
               eta.c_str(), name.c_str(), m_tty ? "" : "\n");
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (m_finished) return;
  m_finished = true;
  if (m_tty) std::fprintf(stderr, "\n");
}

}  // namespace sagrid::app
