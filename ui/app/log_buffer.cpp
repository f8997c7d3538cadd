#include "ui/app/log_buffer.h"

#include <algorithm>

#include "core/common/log.h"

namespace sagrid::ui {

std::vector<LogLine> LogBuffer::lines() const {
  std::lock_guard<std::mutex> lock(m_linesMutex);
  return {m_lines.begin(), m_lines.end()};
}

void LogBuffer::sink_it_(const spdlog::details::log_msg& message) {
  std::lock_guard<std::mutex> lock(m_linesMutex);
  m_lines.push_back({message.level, std::string(message.payload.begin(), message.payload.end())});
  if (m_lines.size() > m_capacity) m_lines.pop_front();
  ++m_total;
}

ScopedLogPanelSink::ScopedLogPanelSink() : m_sink(std::make_shared<LogBuffer>()) {
  m_sink->set_level(spdlog::level::info);
  auto& sinks = logger()->sinks();
  sinks.push_back(m_sink);
  m_previousLevel = logger()->level();
  // The panel shows info; the console sinks keep their own levels.
  for (auto& s : sinks) {
    if (s != m_sink && s->level() < m_previousLevel) s->set_level(m_previousLevel);
  }
  logger()->set_level(std::min(m_previousLevel, spdlog::level::info));
}

ScopedLogPanelSink::~ScopedLogPanelSink() {
  auto& sinks = logger()->sinks();
  sinks.erase(std::remove(sinks.begin(), sinks.end(), m_sink), sinks.end());
  logger()->set_level(m_previousLevel);
}

}  // namespace sagrid::ui
