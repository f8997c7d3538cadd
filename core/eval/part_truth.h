// Hand-marked control parts kept as fixed truth (issue 42). Part marks (ui/app/part_marks_replay.h)
// are steps a curator took in the GUI; "keep" confirms the part the build replaying them finds, so
// replayed by a later build they follow that build's parts and agree with it by construction. The
// parts they confirmed once are kept instead, per object and point, as labels.json keeps a
// control (control_record.h), with the mesh's sha256: `eval --parts --part-truth FILE` measures
// any build against the same parts.
//
// File (JSON):
//   {"objects": {"<object folder>": {"mesh_sha256": "<hex>",
//                                    "points": {"<point, 1-based>": {<its "control">}, ...}}}}
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/dataset/dataset.h"

namespace sagrid {

struct MarkedObject {
  std::string meshSha256;
  std::map<int, nlohmann::json> controls;  // by 1-based point: the confirmed "control" record
};

struct PartTruth {
  std::filesystem::path file;  // for messages
  std::map<std::string, MarkedObject> objects;
};

// The controls the curator confirmed in `entries`' labels, keyed by object folder; objects
// without any are left out. Throws FileError naming a labels file or mesh that cannot be read, or
// an object folder that comes twice.
PartTruth partTruthOf(const std::vector<DatasetEntry>& entries);

// The file's text: one line per marked point, so a changed mark reads as one changed line.
std::string partTruthText(const PartTruth& truth);

// Throws FileError naming `file` for a file not of the form above (a point written other than as
// a plain whole number from 1, an object without points).
PartTruth readPartTruth(const std::filesystem::path& file);
// Several files as one (the wild pool's and Sweet Home 3D's marks together); an object folder in
// two of them is a FileError naming the second.
PartTruth readPartTruths(const std::vector<std::filesystem::path>& files);

}  // namespace sagrid
