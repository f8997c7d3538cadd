// Control parts a curator marked, replayed through the GUI's own session (issue 42): for each
// object of the session's queue that the marks name (by its folder, as datasets lay objects out),
// each listed toggle button point is selected and its control confirmed as found ("keep") or
// reshaped by brush strokes, as the Points panel's Keep button and the viewport's brush do, then
// its axis set if given; or every control is kept, or given one's axis, in one step. The marks
// are written as a person would make them, looking at each part in the GUI; kept in the
// repository, they make the hand-marked parts reproducible.
//
// Marks file (JSON):
//   {"objects": {"<object folder>": [
//      {"point": 3, "keep": true},
//      {"point": 4, "strokes": [{"at": [x, y, z], "radius_cm": 2.5, "mode": "replace"}, ...],
//       "motion": "knob" | "lever" | "button", "axis": "flip" | "x" | "y" | "z" | "own"},
//      {"keep_all": true},                               every control kept as shown (Keep all)
//      {"point": 5, "axis": "z", "for_all": true}]}}     its axis, then This axis for all
// (a knob row shares its panel: every control moving as point 5 does gets its axis).
// A mark's steps run in that order: keep, strokes, motion (the Points panel's motion list), axis.
// `at` in the mesh file's frame and units (the nearest surface point is clicked); `radius_cm` the
// brush's (default 1.5); `mode` replace (the brushed surface alone, Alt+click), add (click, the
// default) or away (Ctrl+click). The axis letters are the GUI's view axes (z up, as its axis
// buttons), not the file's: in a y-up file "z" is the file's y. "own" is the part's own axis of
// rotational symmetry (the panel's "own" button; core/controls/control_symmetry.h).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sagrid::ui {

class Session;

struct PartMarksSummary {
  std::size_t objects = 0, parts = 0;
  // Marks that could not be applied, each naming its object and point; objects not opened.
  std::vector<std::string> problems;
};

// Throws FileError naming `source` for marks that are not of the form above.
PartMarksSummary replayPartMarks(Session& session, const nlohmann::json& marks,
                                 const std::string& source);

}  // namespace sagrid::ui
