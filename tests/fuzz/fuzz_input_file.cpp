#include "fuzz_input_file.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace sagrid::fuzz {
namespace fs = std::filesystem;

namespace {

// One folder per process (fuzzers run in parallel and with -jobs), removed at exit.
const fs::path& inputFolder() {
  static const fs::path folder = [] {
    const fs::path dir = fs::temp_directory_path() / ("sagrid-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(fs::temp_directory_path() / ("sagrid-fuzz-" + std::to_string(::getpid())), ec);
    });
    return dir;
  }();
  return folder;
}

}  // namespace

fs::path writeInputFile(const std::uint8_t* data, std::size_t size, const std::string& fileName) {
  const fs::path path = inputFolder() / fileName;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) std::abort();  // the fuzzing machine itself is broken, not the input
  if (size > 0 && std::fwrite(data, 1, size, file) != size) std::abort();
  std::fclose(file);
  return path;
}

}  // namespace sagrid::fuzz
