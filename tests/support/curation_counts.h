// What a curation left, counted: points of one type, actions of one kind in a curation log.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "core/curation/curation_log.h"
#include "core/labels/labels.h"

namespace sagrid::test {

std::size_t countOfType(const std::vector<AffordancePoint>& points, const std::string& type);
// How many events of `action` the curation log at `log` holds.
std::ptrdiff_t loggedActions(const std::filesystem::path& log, CurationAction action);

}  // namespace sagrid::test
