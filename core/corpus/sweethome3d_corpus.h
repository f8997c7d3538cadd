// The Sweet Home 3D real corpus (issue 10): stoves, sinks and appliance distractors extracted
// from Debian's sweethome3d-furniture libraries (.sh3f) and sweethome3d's default catalog (jar),
// written as SAGrid datasets: OUT/real-train, OUT/real-val (objects with shipped labels, split by
// split.json), OUT/distractors (generated "none" labels), OUT/unlabelled (stoves and sinks with no
// shipped labels yet), each with manifest.jsonl, plus OUT/corpus.json. Mesh, MTL and texture bytes
// are copied exactly as shipped; each object folder gets provenance.json.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/corpus/sweethome3d_catalog.h"
#include "core/corpus/sweethome3d_packages.h"

namespace sagrid {

struct CorpusObjectRecord {
  std::string id;
  std::string library;
  std::string catalogId;
  std::string name;
  CorpusRole role = CorpusRole::None;
  std::string dataset;  // "real-train", "real-val", "distractors" or "unlabelled"
  std::string mesh;     // path relative to the dataset folder
  double metersPerUnit = 0;
  std::vector<std::string> warnings;
};

struct CorpusSummary {
  std::vector<CorpusObjectRecord> objects;
  std::vector<std::string> warnings;  // every object's, prefixed with its id, and skipped entries
  std::map<std::string, int> countsByRole;     // "stove", "sink", "none"
  std::map<std::string, int> countsByDataset;  // "real-train", ...
};

struct SweetHome3dCorpusOptions {
  std::filesystem::path out;
  std::vector<SweetHome3dSource> sources;
  std::filesystem::path labelsDir;  // <id>/labels.json and split.json; absent: nothing labelled
  // Called before each object with (done, total, id).
  std::function<void(std::size_t, std::size_t, const std::string&)> progress;
};

// Builds the corpus in a temporary sibling of `out` and renames it into place at the end, so a
// failure leaves `out` as it was. An existing `out` is replaced only when it is empty or an
// earlier corpus (holds corpus.json). Throws FileError naming the object when a shipped labels
// file's object.sha256 does not match the extracted mesh.
CorpusSummary buildSweetHome3dCorpus(const SweetHome3dCorpusOptions& options);

// Metres per OBJ unit: Sweet Home 3D scales a model to its catalog size, so the sorted catalog
// dimensions (cm) are matched to the sorted mesh extents and the median ratio is taken.
// Returns 0 when no dimension pair is usable.
double estimateMetersPerUnit(const std::vector<double>& catalogSizeCm,
                             const std::vector<double>& meshExtent);

// The axis-aligned extent (x, y, z) of the "v" lines of an OBJ file's text; zeros when none.
std::vector<double> objVertexExtent(std::string_view objText);

}  // namespace sagrid
