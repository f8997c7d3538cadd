#include "core/common/worker_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>

#include "core/common/error.h"

namespace sagrid {

namespace {
void writeAll(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) ::_exit(2);  // the parent is gone: nothing left to report to
    done += static_cast<std::size_t>(n);
  }
}
}  // namespace

WorkerProcess::WorkerProcess(const std::function<void(const Report&)>& body) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw Error(std::string("cannot create a pipe for a worker process: ") + std::strerror(errno));
  std::fflush(nullptr);  // the child must not write the parent's buffered output again
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw Error(std::string("cannot start a worker process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() == 1) ::_exit(2);  // the parent died before prctl
    const int out = fds[1];
    int status = 0;
    try {
      body([out](const std::string& line) { writeAll(out, line + "\n"); });
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sagrid: worker: %s\n", e.what());
      status = 1;
    }
    std::fflush(nullptr);
    ::_exit(status);  // no atexit handlers or static destructors of the parent's state
  }
  ::close(fds[1]);
  m_pid = pid;
  m_fd = fds[0];
}

WorkerProcess::~WorkerProcess() {
  kill();
  if (m_fd >= 0) ::close(m_fd);
}

WorkerProcess::Read WorkerProcess::readLine(std::string& line, double timeoutSeconds) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(timeoutSeconds));
  for (;;) {
    const auto newline = m_buffer.find('\n');
    if (newline != std::string::npos) {
      line = m_buffer.substr(0, newline);
      m_buffer.erase(0, newline + 1);
      return Read::Line;
    }
    if (m_fd < 0) return Read::Ended;
    int waitMs = -1;
    if (timeoutSeconds > 0) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return Read::Timeout;
      waitMs = static_cast<int>(std::min<long long>(left, 1 << 30));
    }
    pollfd p{m_fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, waitMs);
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) return Read::Timeout;
    char chunk[65536];
    const ssize_t n = ::read(m_fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n > 0) {
      m_buffer.append(chunk, static_cast<std::size_t>(n));
      continue;
    }
    ::close(m_fd);  // end of file (or a read error): the child is gone
    m_fd = -1;
    reap(/*block=*/true);
    if (!m_buffer.empty() && m_buffer.back() != '\n') m_buffer += '\n';  // a last partial line
  }
}

void WorkerProcess::kill() {
  if (m_pid < 0) return;
  ::kill(m_pid, SIGKILL);
  reap(/*block=*/true);
}

void WorkerProcess::reap(bool block) {
  if (m_pid < 0) return;
  int status = 0;
  rusage usage{};
  pid_t r;
  do {
    r = ::wait4(m_pid, &status, block ? 0 : WNOHANG, &usage);
  } while (r < 0 && errno == EINTR);
  if (r != m_pid) return;
  m_pid = -1;
  m_peakRssKiB = usage.ru_maxrss;
  if (WIFEXITED(status)) {
    m_cleanExit = WEXITSTATUS(status) == 0;
    m_end = "exited with status " + std::to_string(WEXITSTATUS(status));
  } else if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* name = ::strsignal(sig);
    m_end =
        "killed by signal " + std::to_string(sig) + (name ? std::string(" (") + name + ")" : "");
  } else {
    m_end = "ended";
  }
}

}  // namespace sagrid
