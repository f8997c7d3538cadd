// What annotate writes about controls: for every toggle button point of an object, its control
// part and motion (control_part.h) and, on a stove, the heat source it drives (control_pairing.h),
// as the point's "control" record (control_record.h). Points the curator has set a control for
// keep it; the GUI and the exports read the records.
#pragma once

#include <string>
#include <vector>

#include "core/labels/labels.h"
#include "core/mesh/mesh.h"

namespace sagrid {

class SurfaceScene;

// `mesh` in its z-up frame, as imported for these labels. Returns the warnings of points left a
// site (each naming its point).
std::vector<std::string> annotateControls(ObjectLabels& labels, const Mesh& mesh);
// The same with `scene` built on `mesh` already (annotate has one).
std::vector<std::string> annotateControls(ObjectLabels& labels, const Mesh& mesh,
                                          const SurfaceScene& scene);

}  // namespace sagrid
