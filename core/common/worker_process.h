// A forked child process that runs a function and reports to its parent in lines over a pipe.
// Batch commands run risky per-object work (importers that may hang or crash on hostile files)
// in such a worker: the parent, which stays small and single-threaded, waits for each report with
// a time limit, kills a worker that hangs and starts a fresh one for the rest. A thread cannot
// be stopped safely; a process can, and its memory goes with it.
//
// Fork without exec: the parent must not be running other threads at the fork (only the calling
// thread is copied), which is why it loads nothing heavy before starting workers.
#pragma once

#include <sys/types.h>

#include <functional>
#include <string>

namespace sagrid {

class WorkerProcess {
 public:
  // Sends one line (no newline inside) to the parent.
  using Report = std::function<void(const std::string& line)>;
  // Forks; the child runs body(report) and exits with status 0, or 1 after printing an exception
  // that escaped the body to stderr. The child is killed when the parent dies. Throws Error when
  // the fork or the pipe fails.
  explicit WorkerProcess(const std::function<void(const Report&)>& body);
  ~WorkerProcess();  // kills and reaps a worker still running
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  enum class Read { Line, Timeout, Ended };
  // The next line; Timeout when none came within `timeoutSeconds` (<= 0: wait indefinitely);
  // Ended when the child closed its end (exited or crashed; the child is then reaped).
  Read readLine(std::string& line, double timeoutSeconds);

  void kill();  // SIGKILL and reap; no-op once ended

  bool ended() const { return m_pid < 0; }
  // After the end: "exited with status N" or "killed by signal N (name)".
  const std::string& endDescription() const { return m_end; }
  bool endedCleanly() const { return m_cleanExit; }
  // Peak resident memory of the child in KiB, known after the end (0 before).
  long peakRssKiB() const { return m_peakRssKiB; }

 private:
  void reap(bool block);

  pid_t m_pid = -1;
  int m_fd = -1;
  std::string m_buffer;
  std::string m_end;
  bool m_cleanExit = false;
  long m_peakRssKiB = 0;
};

}  // namespace sagrid
