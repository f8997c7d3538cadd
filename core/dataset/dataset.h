// Reading a dataset folder (DESIGN.md "Dataset"): DIR/manifest.jsonl with one JSON line per object
// ({"id","category","mesh","labels"}), or, without a manifest, every sub-folder holding a
// labels.json and a mesh file (so shared/data/real-dev and hand-made folders work too).
// A manifest's "mesh" and "labels" are references made by data: they are resolved inside the
// dataset folder (no absolute paths, no climbing out with "..", no links leading out; the rule in
// labels_mesh.h), so a stranger's manifest cannot make us read /etc/hostname as a mesh.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sagrid {

struct DatasetEntry {
  std::string id;
  std::string category;  // from the manifest, else from labels.json (may be empty)
  std::filesystem::path mesh;
  std::filesystem::path labels;
};

// Throws FileError for a missing directory or a malformed manifest line (naming the line), and
// for a manifest reference leading outside the dataset folder (or outside `referenceRoot`, a
// wider folder the caller itself chose, e.g. the learning curve's subsets of its --data folder).
// Returns an empty list for a folder with no objects; callers decide whether that is an error.
std::vector<DatasetEntry> readDataset(const std::filesystem::path& directory,
                                      const std::filesystem::path& referenceRoot = {});

// The mesh file in an object folder: mesh.<ext> for an extension importMesh supports first, else
// the only file with such an extension. Empty path when there is none.
std::filesystem::path findMeshFile(const std::filesystem::path& objectDirectory);

}  // namespace sagrid
