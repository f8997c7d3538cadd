// The in-app log panel's sink: an spdlog sink that keeps the last lines for display.
#pragma once

#include <spdlog/details/null_mutex.h>
#include <spdlog/sinks/base_sink.h>

#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace sagrid::ui {

struct LogLine {
  spdlog::level::level_enum level;
  std::string text;
};

class LogBuffer final : public spdlog::sinks::base_sink<std::mutex> {
 public:
  explicit LogBuffer(std::size_t capacity = 500) : m_capacity(capacity) {}
  std::vector<LogLine> lines() const;  // copy, oldest first
  std::size_t total() const { return m_total; }

 protected:
  void sink_it_(const spdlog::details::log_msg& message) override;
  void flush_() override {}

 private:
  mutable std::mutex m_linesMutex;
  std::deque<LogLine> m_lines;
  std::size_t m_capacity;
  std::size_t m_total = 0;
};

// Adds a LogBuffer to sagrid's logger (info level and up) and returns it; removed on destruction
// of the returned handle.
class ScopedLogPanelSink {
 public:
  ScopedLogPanelSink();
  ~ScopedLogPanelSink();
  const LogBuffer& buffer() const { return *m_sink; }

 private:
  std::shared_ptr<LogBuffer> m_sink;
  spdlog::level::level_enum m_previousLevel;
};

}  // namespace sagrid::ui
