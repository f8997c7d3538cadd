// Some objects of one or more datasets as a dataset folder of its own (the learning curve's and
// the guards' folds): a manifest listing the objects where they really are, read with the folder
// holding them all as readDataset's referenceRoot, so no object is copied.
#pragma once

#include <filesystem>
#include <vector>

#include "core/dataset/dataset.h"

namespace sagrid {

// The folder that holds `files` where they really are: `dataDir` widened to the common ancestor
// of the files' real paths (object folders may be symbolic links to elsewhere, a dataset assembled
// with `ln -s`, which readDataset follows). A subset of `dataDir` is read with it as referenceRoot.
std::filesystem::path folderHoldingFiles(const std::filesystem::path& dataDir,
                                         const std::vector<std::filesystem::path>& files);

// Writes dir/manifest.jsonl listing `objects` (id, category as given, mesh and labels relative to
// `dir`, links resolved: manifest paths are never absolute).
void writeDatasetSubset(const std::filesystem::path& dir,
                        const std::vector<const DatasetEntry*>& objects);

}  // namespace sagrid
