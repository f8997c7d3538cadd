// A time limit on one mesh import. An import that finishes past its deadline is a FileError
// naming the file (assimp is also asked to stop through its progress reports, which some of its
// loaders honour; the OBJ loader does not). A loader that spins cannot be stopped from inside the
// process: where the caller allows it (the command line, not the GUI, which would lose unsaved
// work), the process then ends with that one-line error and exit status 1 a few seconds later.
#pragma once

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace Assimp {
class ProgressHandler;
}

namespace sagrid {

struct ImportTimeLimit {
  double seconds = 0;           // <= 0: no limit
  bool exitProcess = false;     // end the process when a loader does not stop by itself
  double exitGraceSeconds = 5;  // after the deadline, before exitProcess ends the process
};

// The limit importMesh applies; the command line sets it from --import-time-limit.
void setImportTimeLimit(const ImportTimeLimit& limit);
ImportTimeLimit importTimeLimit();

// Watches one import while it is alive (no thread and no effect when the limit is off).
class ImportDeadline {
 public:
  ImportDeadline(std::filesystem::path path, const ImportTimeLimit& limit);
  ~ImportDeadline();
  ImportDeadline(const ImportDeadline&) = delete;
  ImportDeadline& operator=(const ImportDeadline&) = delete;

  // For Assimp::Importer::SetProgressHandler (which takes ownership); nullptr when there is no
  // limit.
  Assimp::ProgressHandler* newProgressHandler() const;
  bool expired() const;
  // "import did not finish within N s ..." for the FileError.
  std::string problem() const;

 private:
  void watch();

  std::filesystem::path m_path;
  ImportTimeLimit m_limit;
  std::chrono::steady_clock::time_point m_deadline;
  std::mutex m_mutex;
  std::condition_variable m_finished;
  bool m_done = false;
  std::thread m_watchdog;
};

}  // namespace sagrid
