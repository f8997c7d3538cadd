// Runs per-object work over a collection so that a batch survives what its objects do to it:
// the work happens in a worker process (core/common/worker_process.h) that loads its models once
// and reports each object; an object that takes longer than the time limit (an importer that
// hangs) or crashes the worker is recorded as failed, the worker is replaced and the batch goes
// on with the next object. Every outcome is appended to the run manifest as it happens
// (core/annotate/run_manifest.h), so an interrupted batch has recorded everything it finished.
// Only a problem with the output itself (read-only, full disk) stops the batch: it would fail
// every object that follows.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/annotate/shard.h"
#include "core/mesh/mesh_files.h"

namespace sagrid {

// Object statuses in the manifest and the summary.
namespace batch_status {
inline constexpr const char* kAnnotated = "annotated";
inline constexpr const char* kUpToDate =
    "up-to-date";                                   // skipped: labels match mesh, models, options
inline constexpr const char* kCurated = "curated";  // skipped: a person's labels, kept
inline constexpr const char* kBusy = "busy";        // skipped: another task holds its lock
inline constexpr const char* kFailed = "failed";
}  // namespace batch_status

// The work on one object, run in the worker. Returns a JSON object with at least "status" (one
// of batch_status) and, as it applies, "error", "category", "points", "seconds", "models".
// "output_error": true in a failed result means the output cannot be written: the batch stops.
// It should not throw; an exception is recorded as a failure of the object.
using ObjectTask = std::function<nlohmann::json(const MeshFile& file)>;
// Runs once in each worker before its first object (loads models); returns the task. An
// exception here stops the batch with its message.
using WorkerSetup = std::function<ObjectTask()>;

struct BatchOptions {
  std::filesystem::path out;       // created; must be writable
  std::filesystem::path manifest;  // default out/annotate.jsonl
  Shard shard;                     // recorded in the manifest (files are already the shard's)
  double timeLimitSeconds = 600;   // per object; <= 0: none
  // A worker is replaced by a fresh one after this many objects (0: never), so that memory a
  // library keeps between objects (allocator fragmentation, caches) cannot grow over thousands
  // of objects; a fresh worker costs one model load.
  std::size_t objectsPerWorker = 100;
  // Called when an object starts (done = objects finished so far) and when the batch ends.
  std::function<void(std::size_t done, const std::string& current)> onProgress;
  // Called with each manifest line (e.g. to print failures).
  std::function<void(const nlohmann::json& line)> onOutcome;
};

struct BatchSummary {
  std::size_t objects = 0;
  std::map<std::string, std::size_t> byStatus;  // status -> objects
  std::size_t points = 0;
  std::size_t workerRestarts = 0;
  double seconds = 0;
  long peakWorkerRssKiB = 0;

  std::size_t count(const std::string& status) const;
  // "12 objects: 10 annotated, 1 up-to-date, 0 curated, 0 busy, 1 failed; 35 points; 42.0 s"
  std::string line() const;
};

// Throws FileError naming OUT when it cannot be created or written (checked with a probe file
// before any object is touched; nothing else is written then).
void requireWritableFolder(const std::filesystem::path& out);

// Throws FileError for an output that cannot be written, Error when a worker cannot start
// (setup failed); per-object problems are outcomes, not exceptions.
BatchSummary runBatch(const std::vector<MeshFile>& files, const BatchOptions& options,
                      const WorkerSetup& setup);

}  // namespace sagrid
