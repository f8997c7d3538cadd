// The curator's changes to a toggle button's control (issue 42): the Points panel's motion, axis,
// pivot, burner, Keep, Grow and Shrink, and the viewport's part brush. Each change is one undoable
// SetControlCommand of a record the curator confirmed; a reshaped part is the curator's
// ("marked"), its motion, axis and pivot found again from the new shape, the burner it drives
// kept.
#pragma once

#include <string>
#include <vector>

#include "ui/document/control_view.h"

namespace sagrid {
struct SurfaceHit;
}

namespace sagrid::ui {

class Session;

// The brush of the viewport: while armed, a click on the surface adds the connected surface
// within the radius to the selected toggle button's part, Ctrl+click takes it away, Alt+click
// starts the part anew with it (core/controls/control_part_edit.h: brushedPart).
struct PartBrush {
  bool armed = false;
  float radiusCm = 1.5f;
};

// Writes `shown` as point `index`'s record, confirmed by the curator; `what` names the step.
void setControlRecord(Session& session, int index, const ShownControl& shown, const std::string& what);

// One undo step for every toggle button of the open object: each shown control confirmed as it
// is ("Keep all"), or, with `axisOf` a toggle button's index, each control moving as that one
// does (knob, lever or button) given its axis too ("This axis for all": a row of knobs shares
// its panel). Returns how many records were written.
std::size_t confirmEveryControl(Session& session, int axisOf = -1);

// Point `index`'s control moving as `motion` (the Points panel's motion list), its part and axis
// kept, a knob's or button's pivot moved to the part's middle; one undoable step where it moved
// otherwise. False (nothing done) when the point has no control.
bool setControlMotion(Session& session, int index, ControlMotion motion);

// Point `index`'s knob axis set to its part's axis of rotational symmetry (core/controls/
// control_symmetry.h: a knob leaning with a sloped panel), pointing the way the shown axis did;
// one undoable step (none where the curator's record turns about it already). False (nothing
// done) when the point's control is no knob (a lever arm is nearly symmetric about its length) or
// has no part with area.
bool setOwnAxis(Session& session, int index);

// Gives point `index` (a toggle button) the part of `triangles` (mesh indices); nothing when they
// are empty or the part's already. Returns whether a command ran.
bool reshapeControlPart(Session& session, int index, std::vector<int> triangles,
                        const std::string& what);

// A click adds the brushed surface, Ctrl+click takes it away, Alt+click makes it the whole part.
enum class BrushMode { Add, Away, Replace };

// Whether a click of the armed brush reshapes something: a toggle button is selected.
bool brushApplies(const Session& session);

// The brush at `hit` (on the open document's surface) on the selected point's part. False when
// no toggle button is selected or nothing changed.
bool brushControlPart(Session& session, const SurfaceHit& hit, BrushMode mode);

}  // namespace sagrid::ui
