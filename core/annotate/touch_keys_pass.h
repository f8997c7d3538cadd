// The touch-key pass: the flat pads of a stove's touch controls (core/points/touch_keys.h) become
// its toggle points, as the texture pass does with printed touch symbols, for the hobs whose keys
// are geometry too thin for the network to see. It runs where the texture pass gives a type no
// marks; `--no-touch-keys` switches it off.
#pragma once

#include <string>
#include <vector>

#include "core/annotate/printed_marks_pass.h"
#include "core/geometry/connected_parts.h"

namespace sagrid {

struct Normalization;
class SurfaceScene;

// The touch keys of an object of `category`, as circles in the z-up mesh frame (support 1):
// searched only on stoves, else empty at no cost. `parts` from normalizedParts
// (core/annotate/repeated_parts_pass.h), `resolution` the grid's.
std::vector<PrintedCircle> touchKeysOf(const std::string& category,
                                       const std::vector<ConnectedPart>& parts,
                                       const SurfaceScene& scene,
                                       const Normalization& normalization, int resolution);

// The keys as the marks of `type` (applyPrintedMarks): a stove's toggle buttons, the keys instead
// of the model's own points; other types get none.
MarksForType touchKeysFor(const std::vector<PrintedCircle>& keys, const std::string& type);

}  // namespace sagrid
