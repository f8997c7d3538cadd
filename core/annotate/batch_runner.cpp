#include "core/annotate/batch_runner.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "core/annotate/run_manifest.h"
#include "core/common/atomic_file.h"
#include "core/common/elapsed.h"
#include "core/common/error.h"
#include "core/common/worker_process.h"
#include "core/labels/labels.h"

namespace sagrid {
namespace fs = std::filesystem;

namespace {
// The least time a worker gets to load its models when objects have a time limit.
constexpr double kSetupLimitSeconds = 300;

std::string hostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

// The body of a worker: set up once, then report "start I" and "done I <json>" for each object
// from `first` on, and "retire" when it has done `quota` objects (0: no quota) with objects left.
// A setup failure is reported as "fatal <message>".
void workerBody(const std::vector<MeshFile>& files, std::size_t first, std::size_t quota,
                const WorkerSetup& setup, const WorkerProcess::Report& report) {
  ObjectTask task;
  try {
    task = setup();
  } catch (const std::exception& e) {
    report(std::string("fatal ") + e.what());
    return;
  }
  report("ready");
  for (std::size_t i = first; i < files.size(); ++i) {
    if (quota > 0 && i - first == quota) {
      report("retire");
      return;
    }
    report("start " + std::to_string(i));
    nlohmann::json result;
    try {
      result = task(files[i]);
    } catch (const std::exception& e) {
      result = {{"status", batch_status::kFailed}, {"error", e.what()}};
    }
    report(
        "done " + std::to_string(i) + " " +
        result.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));  // non-UTF-8 paths
  }
}

// "start 12" / "done 12 {...}" -> 12 and the rest; false for anything else.
bool parseReport(const std::string& line, const std::string& verb, std::size_t& index,
                 std::string& rest) {
  if (line.rfind(verb + " ", 0) != 0) return false;
  const std::string tail = line.substr(verb.size() + 1);
  const auto space = tail.find(' ');
  try {
    index = std::stoul(tail.substr(0, space));
  } catch (const std::exception&) {
    return false;
  }
  rest = space == std::string::npos ? "" : tail.substr(space + 1);
  return true;
}
}  // namespace

std::size_t BatchSummary::count(const std::string& status) const {
  const auto it = byStatus.find(status);
  return it == byStatus.end() ? 0 : it->second;
}

std::string BatchSummary::line() const {
  using namespace batch_status;
  char text[512];
  std::snprintf(text, sizeof text,
                "%zu objects: %zu annotated, %zu up-to-date, %zu curated, %zu busy, %zu failed; "
                "%zu points; %.1f s",
                objects, count(kAnnotated), count(kUpToDate), count(kCurated), count(kBusy),
                count(kFailed), points, seconds);
  return text;
}

void requireWritableFolder(const fs::path& out) {
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec || !fs::is_directory(out))
    throw FileError(out, "cannot create the output folder: " +
                             (ec ? ec.message() : std::string("a file of that name exists")));
  const std::string probePrefix = ".sagrid-write-probe-";
  const fs::path probe = out / (probePrefix + std::to_string(::getpid()));
  try {
    writeFileAtomic(probe, "probe\n");
  } catch (const Error& e) {
    throw FileError(out, std::string("the output folder cannot be written (") + e.what() +
                             "); nothing was written");
  }
  // This run's probe, and any a run killed between writing and removing its own left behind (a
  // run beside this one in a Slurm array loses nothing: its probe has done its work once written).
  std::error_code removing;
  for (fs::directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind(probePrefix, 0) == 0) fs::remove(it->path(), removing);
  fs::remove(probe, removing);
}

BatchSummary runBatch(const std::vector<MeshFile>& files, const BatchOptions& options,
                      const WorkerSetup& setup) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  requireWritableFolder(options.out);
  const fs::path manifest =
      options.manifest.empty() ? options.out / kRunManifestFile : options.manifest;
  const std::string host = hostName();
  BatchSummary summary;
  summary.objects = files.size();
  std::size_t finished = 0;

  auto record = [&](std::size_t i, nlohmann::json result) {
    nlohmann::json line{{"object", files[i].id}, {"mesh", files[i].path.string()}};
    line.update(result);
    line.erase("output_error");
    line["shard"] = options.shard.toString();
    line["host"] = host;
    line["time"] = currentUtcTimestamp();
    const std::string status = line.value("status", std::string(batch_status::kFailed));
    ++summary.byStatus[status];
    if (line.contains("points") && line["points"].is_number_unsigned())
      summary.points += line["points"].get<std::size_t>();
    ++finished;
    appendManifestLine(manifest, line);
    if (options.onOutcome) options.onOutcome(line);
    if (result.value("output_error", false))
      throw FileError(options.out,
                      "cannot write the output: " + line.value("error", std::string()) +
                          " (the batch stops; labels already written are complete)");
  };

  std::size_t next = 0;
  while (next < files.size()) {
    WorkerProcess worker([&](const WorkerProcess::Report& report) {
      workerBody(files, next, options.objectsPerWorker, setup, report);
    });
    std::string line;
    // Setup (model loading) does not depend on the objects: a generous limit of its own, and a
    // setup that hangs stops the batch (every worker would hang the same way).
    const double setupLimit =
        options.timeLimitSeconds > 0 ? std::max(options.timeLimitSeconds, kSetupLimitSeconds) : 0;
    const auto ready = worker.readLine(line, setupLimit);
    if (ready == WorkerProcess::Read::Timeout)
      throw Error("the worker process did not load its models within " +
                  std::to_string(static_cast<int>(setupLimit)) + " s");
    if (ready != WorkerProcess::Read::Line || line.rfind("fatal ", 0) == 0) {
      if (line.rfind("fatal ", 0) == 0) throw Error(line.substr(6));
      throw Error("the worker process could not start (" + worker.endDescription() + ")");
    }
    if (line != "ready") throw Error("the worker process sent an unexpected report: " + line);
    std::size_t current = next;
    bool replaced = false;
    while (!replaced && next < files.size()) {
      std::string rest;
      const auto r = worker.readLine(line, options.timeLimitSeconds);
      if (r != WorkerProcess::Read::Line) {
        // Ended or stalled between two objects (it crashed or was stopped after a report): the
        // next object is counted as failed so that a worker that keeps dying cannot loop forever.
        if (r == WorkerProcess::Read::Timeout) worker.kill();
        record(next, {{"status", batch_status::kFailed},
                      {"error", "the worker process " +
                                    (r == WorkerProcess::Read::Timeout ? std::string("stalled")
                                                                       : worker.endDescription()) +
                                    " before starting this object"}});
        ++next;
        replaced = true;
        break;
      }
      if (line == "retire") break;  // its quota done: a fresh worker takes the rest
      if (!parseReport(line, "start", current, rest))
        throw Error("the worker process sent an unexpected report: " + line);
      if (options.onProgress) options.onProgress(finished, files[current].id);
      const auto done = worker.readLine(line, options.timeLimitSeconds);
      std::size_t doneIndex = 0;
      if (done == WorkerProcess::Read::Line && parseReport(line, "done", doneIndex, rest) &&
          doneIndex == current) {
        auto result = nlohmann::json::parse(rest, nullptr, /*allow_exceptions=*/false);
        if (!result.is_object())
          result = {{"status", batch_status::kFailed}, {"error", "unreadable worker report"}};
        next = current + 1;
        record(current, std::move(result));
        continue;
      }
      std::string error;
      if (done == WorkerProcess::Read::Timeout) {
        worker.kill();
        char text[200];
        std::snprintf(text, sizeof text,
                      "no result within the time limit of %.0f s (the importer or the feature "
                      "extraction hung); the worker was stopped",
                      options.timeLimitSeconds);
        error = text;
      } else if (done == WorkerProcess::Read::Ended) {
        error = "the worker process " + worker.endDescription() + " while working on this object";
      } else {
        worker.kill();
        error = "the worker process sent an unexpected report: " + line;
      }
      next = current + 1;
      replaced = true;
      record(current, {{"status", batch_status::kFailed}, {"error", error}});
    }
    if (!replaced) {
      worker.readLine(line, 0);  // waits for the worker's exit
    } else if (next < files.size()) {
      ++summary.workerRestarts;
    }
    worker.kill();
    summary.peakWorkerRssKiB = std::max(summary.peakWorkerRssKiB, worker.peakRssKiB());
  }
  summary.seconds = secondsSince(start);
  if (options.onProgress) options.onProgress(finished, "");
  return summary;
}

}  // namespace sagrid
