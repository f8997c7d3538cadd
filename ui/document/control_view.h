// The control of a toggle button point as the GUI shows and edits it: the point's record, else the
// part the exports would find on the mesh (core/controls), in the mesh's z-up frame. Found parts
// are kept until the document changes, so drawing a selected point costs nothing per frame.
#pragma once

#include <optional>
#include <string>

#include "core/controls/control_part.h"
#include "core/mesh/mesh.h"

namespace sagrid::ui {

class AnnotationDocument;

struct ShownControl {
  ControlPart part;            // z-up mesh frame
  bool recorded = false;       // from labels.json; else found now
  bool confirmed = false;      // the record is the curator's (control_record.h)
  // The record's burner (an index among the heat sources); for a part found now, the one the
  // layout pairs it with, as annotate and the exports would.
  std::optional<int> drives;
  std::string warning;         // why a found one is a disc or missing
};

// Nullopt for points that are not toggle buttons, and where no part can move (warning then lost:
// see findControlParts). Throws nothing: a malformed record reads as none.
std::optional<ShownControl> shownControl(const AnnotationDocument& document, int index);

// The document's mesh with the shown control of every toggle button moved as the exports move it
// (core/controls/control_turn.h): knobs and levers turned by `angle` radians, buttons pressed home
// (pressAtTurn). The mesh itself where no control moves.
Mesh meshWithControlsTurned(const AnnotationDocument& document, float angle);

}  // namespace sagrid::ui
