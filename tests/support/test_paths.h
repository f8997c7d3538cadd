// Paths tests use: the sagrid binary, shipped test data, shared/ data, and per-test temp dirs.
#pragma once

#include <filesystem>
#include <string>

namespace sagrid::test {

std::filesystem::path sagridBinary();
std::filesystem::path sharedDir();        // ../shared beside the repository
std::filesystem::path realDevDir();       // ../shared/data/real-dev
// A fresh empty directory unique to the running test, removed and recreated on each call.
std::filesystem::path freshTempDir(const std::string& name = "");

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};
// Runs a shell command line and captures its output.
CommandResult runCommand(const std::string& commandLine);
// Runs the sagrid binary with the given (already shell-quoted) arguments.
CommandResult runSagrid(const std::string& arguments);
// The same from the repository's root, so that arguments name shipped files as a user in a
// checkout types them (`--init resources/models`).
CommandResult runSagridInSource(const std::string& arguments);
std::string shellQuote(const std::string& text);
// A path quoted for a shell command line.
inline std::string quotedPath(const std::filesystem::path& path) {
  return shellQuote(path.string());
}

}  // namespace sagrid::test
