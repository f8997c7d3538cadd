// `sagrid annotate` over a collection: the per-object work of a resumable, shardable batch
// (core/annotate/batch_runner.h runs it). For each object, in the worker process:
//  - take the object's lock, OUT/.locks/<id>.lock (another task on it: "busy", skipped);
//  - an existing OUT/<id>/labels.json that a person curated (isCurated) is kept ("curated"), and
//    one predicted from the same mesh, models and options (matchesFingerprint) is skipped
//    ("up-to-date"); --force redoes both; an unreadable one fails the object, never overwritten;
//  - annotate and write labels.json atomically, with the fingerprint in its prediction block.
#pragma once

#include <filesystem>

#include "core/annotate/annotate.h"
#include "core/annotate/batch_runner.h"

namespace sagrid {

struct AnnotateBatchSettings {
  std::filesystem::path modelsDir;
  AnnotateOptions options;
  std::filesystem::path out;
  bool force = false;
};

inline constexpr const char* kObjectLocksFolder = ".locks";

// Loads the models (in the worker), takes the feature backend and grid size from their cards and
// the confidence map from their folder (settings.options' own are replaced), and returns the
// per-object task described above.
WorkerSetup annotateWorkerSetup(const AnnotateBatchSettings& settings);

}  // namespace sagrid
