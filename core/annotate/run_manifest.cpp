#include "core/annotate/run_manifest.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"

namespace sagrid {

void appendManifestLine(const std::filesystem::path& manifest, const nlohmann::json& line) {
  // Non-UTF-8 file names must not make the write throw (issue 14): such bytes become U+FFFD.
  const std::string bytes =
      line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  const int fd = ::open(manifest.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    throw FileError(manifest, std::string("cannot open run manifest: ") + std::strerror(errno));
  std::string problem;
  while (::flock(fd, LOCK_EX) != 0 && errno == EINTR) {
  }
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      problem = std::strerror(n < 0 ? errno : EIO);
      // Cut back a partial line so the file stays whole lines.
      if (done > 0) {
        const off_t end = ::lseek(fd, 0, SEEK_END);
        if (end >= static_cast<off_t>(done)) (void)::ftruncate(fd, end - static_cast<off_t>(done));
      }
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);  // releases the lock
  if (!problem.empty()) throw FileError(manifest, "cannot append to run manifest: " + problem);
}

std::vector<nlohmann::json> readManifest(const std::filesystem::path& manifest) {
  std::istringstream in(readFileBytes(manifest));
  std::vector<nlohmann::json> lines;
  std::string line;
  while (std::getline(in, line)) {
    auto j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (j.is_object()) lines.push_back(std::move(j));
  }
  return lines;
}

std::map<std::string, nlohmann::json> latestByObject(const std::vector<nlohmann::json>& lines) {
  std::map<std::string, nlohmann::json> latest;
  for (const auto& l : lines)
    if (l.contains("object") && l["object"].is_string()) latest[l["object"]] = l;
  return latest;
}

}  // namespace sagrid
