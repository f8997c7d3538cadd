#include "core/model/model_files.h"

#include <vector>

namespace sagrid::model {

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> filesOf(const fs::path& folder, const std::string& modelName) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(folder)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    if (!modelName.empty() && name.rfind(modelName + ".", 0) != 0) continue;
    files.push_back(e.path());
  }
  return files;
}

}  // namespace

void copyModelFiles(const fs::path& from, const fs::path& to, const std::string& modelName) {
  fs::create_directories(to);
  for (const auto& file : filesOf(from, modelName)) {
    const fs::path target = to / file.filename();
    std::error_code ec;
    // A folder of links to the models it is copied from already holds them (copying a file onto
    // itself fails).
    if (fs::equivalent(file, target, ec)) continue;
    fs::copy_file(file, target, fs::copy_options::overwrite_existing);
  }
}

void moveModelFiles(const fs::path& from, const fs::path& to, const std::string& modelName) {
  fs::create_directories(to);
  for (const auto& file : filesOf(from, modelName)) fs::rename(file, to / file.filename());
}

}  // namespace sagrid::model
