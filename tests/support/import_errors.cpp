#include "support/import_errors.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/common/error.h"

namespace sagrid::test {

std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string importError(const std::filesystem::path& path, const ImportOptions& options) {
  try {
    importMesh(path, options);
  } catch (const FileError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;  // names the file first
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    return message;
  }
  ADD_FAILURE() << path << " imported without error";
  return "";
}

}  // namespace sagrid::test
