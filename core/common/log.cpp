#include "core/common/log.h"

#include <spdlog/sinks/stdout_color_sinks.h>

namespace sagrid {

std::shared_ptr<spdlog::logger> logger() {
  static std::shared_ptr<spdlog::logger> instance = [] {
    auto sink = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
    auto created = std::make_shared<spdlog::logger>("sagrid", sink);
    created->set_pattern("%^%l%$: %v");
    created->set_level(spdlog::level::warn);
    return created;
  }();
  return instance;
}

void setLogLevel(spdlog::level::level_enum level) { logger()->set_level(level); }

}  // namespace sagrid
