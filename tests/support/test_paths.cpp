#include "support/test_paths.h"

#include <unistd.h>

#include <array>
#include <cstdio>
#include <sys/wait.h>

#include <gtest/gtest.h>

namespace sagrid::test {
namespace fs = std::filesystem;

fs::path sagridBinary() { return SAGRID_BINARY; }
fs::path sharedDir() { return fs::weakly_canonical(SAGRID_SHARED_DIR); }
fs::path realDevDir() { return sharedDir() / "data" / "real-dev"; }

fs::path freshTempDir(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  // Outside a test (a suite's SetUpTestSuite) the folder is per process: CTest runs the tests of
  // one suite as parallel processes, and each would otherwise wipe the others' shared folder.
  std::string leaf = info ? std::string(info->test_suite_name()) + "." + info->name()
                          : "suite." + std::to_string(::getpid());
  if (!name.empty()) leaf += "." + name;
  fs::path dir = fs::temp_directory_path() / "sagrid-tests" / leaf;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'') quoted += "'\\''";
    else quoted += c;
  }
  return quoted + "'";
}

CommandResult runCommand(const std::string& commandLine) {
  CommandResult result;
  FILE* pipe = ::popen((commandLine + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

CommandResult runSagrid(const std::string& arguments) {
  return runCommand(shellQuote(sagridBinary().string()) + " " + arguments);
}

CommandResult runSagridInSource(const std::string& arguments) {
  return runCommand("cd " + shellQuote(SAGRID_SOURCE_DIR) + " && " +
                    shellQuote(sagridBinary().string()) + " " + arguments);
}

}  // namespace sagrid::test
