// The texture pass: circles printed on a stove's top (core/features/printed_marks.h) become points
// of the model whose type they stand for — a cooking zone a heat source, a touch symbol outside
// the zones a toggle button — for glass hobs whose zones and controls have no geometry the network
// could find. The model's field takes the distance to the nearest mark where that is smaller (so
// the paper's argmin and a known count see them too); the automatic count takes every mark as a
// point, zones instead of the model's own heat-source points; symbols instead of the model's
// toggle points when there are at least two (a touch panel), else beside those of them that lie
// beyond the model's suppression radius of the symbol. Only a printed hob counts: 1-8 zones, and
// symbols only beside zones and at most 24 of them (more circles are a pattern, not a hob).
#pragma once

#include <string>
#include <vector>

#include "core/annotate/annotate.h"
#include "core/features/printed_marks.h"

namespace sagrid {

// The printed marks of an object of `category`: searched only where some mark stands for one of
// its types (stoves), else empty at no cost.
PrintedMarks printedMarksOf(const Mesh& mesh, const std::string& category);

struct MarksForType {
  std::vector<PrintedCircle> circles;  // empty when no mark stands for the type
  bool replaceModelPoints = false;     // the automatic count keeps only the marks
};

// The marks that stand for `type` on an object of `category`.
MarksForType printedMarksFor(const PrintedMarks& marks, const std::string& category,
                             const std::string& type);

// Applies the marks (as above) to a prediction `model` made with `mode` (and `count`); unchanged
// when there are none.
void applyPrintedMarks(const model::AffordanceModel& model, ModelPrediction& prediction,
                       const MarksForType& marks, const FeatureGrid& features,
                       const SurfaceScene& scene, UpAxis fileUp, InstanceMode mode, int count = 1);

}  // namespace sagrid
