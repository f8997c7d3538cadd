// A toggle button's control as labels.json keeps it, in the point's "control" field (DESIGN.md):
//   "control": {"motion": "knob"|"lever"|"button", "joint": "hinge"|"slide",
//               "part": {"origin": "connected"|"material"|"grown"|"disc"|"marked",
//                        "triangles": [[first, count], ...]},   runs of imported triangle indices
//               "axis": [x, y, z], "pivot": [x, y, z], "radius": r,   the mesh file's frame and units
//               "drives": k,   a stove knob: the k-th heat source point (0-based), -1 none
//               "confirmed": true}   set by the curator in the GUI (kept, reshaped or turned)
// `joint` is written for readers (it follows from `motion`); `drives` is absent where nothing was
// paired (sinks), `confirmed` absent where annotate wrote the record. Written by annotate, changed by the
// curator in the GUI, read by the exports; `sagrid eval --parts` measures found parts against the
// confirmed ones.
#pragma once

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "core/controls/control_part.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh.h"

namespace sagrid {

inline constexpr const char* kControlField = "control";

struct ControlRecord {
  ControlPart part;  // the mesh's z-up frame and units
  std::optional<int> drives;
  bool confirmed = false;  // the curator's: kept, reshaped or turned in the GUI
};

// `part` in the z-up frame of a mesh whose file is `fileUp`; the record is in the file's frame.
nlohmann::json controlJson(const ControlRecord& record, UpAxis fileUp);
// The point's record, or nullopt when it has none. Throws FileError naming `pathForErrors` and the
// field for a malformed one (wrong types, unknown motion or origin, non-finite numbers, a zero
// axis, negative or overlapping triangle runs, more runs than kMaxControlRuns).
std::optional<ControlRecord> readControlRecord(const AffordancePoint& point, UpAxis fileUp,
                                               const std::filesystem::path& pathForErrors);
void writeControlRecord(AffordancePoint& point, const ControlRecord& record, UpAxis fileUp);

inline constexpr std::size_t kMaxControlRuns = 100000;

}  // namespace sagrid
