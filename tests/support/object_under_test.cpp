#include "support/object_under_test.h"

#include "core/features/feature_pipeline.h"
#include "support/synthetic_fields.h"
#include "support/untrained_models.h"

namespace sagrid::test {

void ObjectUnderTest::finish() {
  FeatureOptions options;
  options.views = 12;
  grid = computeFeatures(mesh, options);
  scene = std::make_unique<SurfaceScene>(mesh);
}

ModelPrediction ObjectUnderTest::predicted(const std::string& model,
                                           const std::vector<Eigen::Vector3f>& centres,
                                           const std::vector<float>& offsets,
                                           const ExtractionSettings& extraction) const {
  return predictionFromField(untrainedModelFor(model, grid), fieldTowards(grid, centres, offsets),
                             grid, *scene, UpAxis::Z, InstanceMode::Auto, 1, &extraction);
}

}  // namespace sagrid::test
