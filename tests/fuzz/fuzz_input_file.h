// libFuzzer targets feed their input through the same file code path users hit: the bytes are
// written to a file with the right name in a folder private to the fuzzing process, and the
// loader opens it. A target fails (crash, sanitizer report, uncaught non-sagrid exception) only
// on our bugs; every sagrid::Error is the expected answer to bad input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace sagrid::fuzz {

// Writes `data` to <private folder>/<fileName> (replacing the previous input) and returns its path.
std::filesystem::path writeInputFile(const std::uint8_t* data, std::size_t size,
                                     const std::string& fileName);

}  // namespace sagrid::fuzz
