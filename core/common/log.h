// The one levelled logger of SAGrid (spdlog). Core logs through it and never prints directly;
// the CLI adds a console sink, the GUI an in-app log panel sink.
#pragma once

#include <memory>

#include <spdlog/logger.h>

namespace sagrid {

std::shared_ptr<spdlog::logger> logger();
void setLogLevel(spdlog::level::level_enum level);

}  // namespace sagrid
