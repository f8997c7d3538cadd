#include "core/annotate/printed_marks_pass.h"

#include <algorithm>
#include <limits>

#include "core/annotate/category_rules.h"
#include "core/features/feature_grid.h"
#include "core/model/affordance_model.h"

namespace sagrid {

namespace {
bool marksStandForItsTypes(const std::string& category) {
  return categoryRulesFor(category).printedMarks;
}
// More circles than a hob has zones or touch symbols are a pattern (fries in a fryer, polka
// dots), not a hob.
constexpr std::size_t kMostZones = 8, kMostSymbols = 24;
}  // namespace

PrintedMarks printedMarksOf(const Mesh& mesh, const std::string& category) {
  return marksStandForItsTypes(category) ? findPrintedMarks(mesh) : PrintedMarks{};
}

MarksForType printedMarksFor(const PrintedMarks& marks, const std::string& category,
                             const std::string& type) {
  if (!marksStandForItsTypes(category) || marks.zones.empty() || marks.zones.size() > kMostZones)
    return {};
  if (type == "heatsource") return {marks.zones, true};
  if (type == "togglebutton" && marks.symbols.size() <= kMostSymbols)
    return {marks.symbols, marks.symbols.size() >= 2};
  return {};
}

void applyPrintedMarks(const model::AffordanceModel& model, ModelPrediction& prediction,
                       const MarksForType& forType, const FeatureGrid& features,
                       const SurfaceScene& scene, UpAxis fileUp, InstanceMode mode, int count) {
  const std::vector<PrintedCircle>& marks = forType.circles;
  if (marks.empty()) return;
  const Normalization& n = features.normalization;
  std::vector<Eigen::Vector3f> centres;
  for (const PrintedCircle& m : marks) centres.push_back(n.toNormalized(m.centre));
  PredictedField& field = prediction.field;
  for (std::size_t v = 0; v < field.voxels.size(); ++v) {
    const Eigen::Vector3f c = voxelCenter(field.voxels[v], field.resolution);
    float nearest = std::numeric_limits<float>::infinity();
    for (const Eigen::Vector3f& m : centres) nearest = std::min(nearest, (c - m).norm());
    field.distances[v] = std::min(field.distances[v], nearest);
  }
  if (mode != InstanceMode::Auto) {
    prediction = predictionFromField(model, std::move(prediction.field), features, scene, fileUp,
                                     mode, count);
    return;
  }
  const ExtractionSettings& extraction = model.card().extraction;
  std::vector<ExtractedPoint> points;
  std::vector<SurfacePoint> surface;
  for (std::size_t i = 0; i < marks.size(); ++i) {
    points.push_back({centres[i], 0.0f, marks[i].support});
    surface.push_back(projectToSurface(centres[i], n, scene, fileUp));
  }
  if (!forType.replaceModelPoints) {
    for (std::size_t i = 0; i < prediction.points.size(); ++i) {
      const Eigen::Vector3f& p = prediction.points[i].position;
      const bool nearMark = std::any_of(
          centres.begin(), centres.end(),
          [&](const Eigen::Vector3f& m) { return (p - m).norm() < extraction.nmsRadius; });
      if (nearMark) continue;
      points.push_back(prediction.points[i]);
      surface.push_back(prediction.surface[i]);
    }
  }
  prediction.points = std::move(points);
  prediction.surface = std::move(surface);
}

}  // namespace sagrid
