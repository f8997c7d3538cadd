// A mesh with its features and surface scene, and a model's prediction on it from a field with
// known minima: for the tests of the passes that run after the automatic count.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/annotate/annotate.h"
#include "core/features/feature_grid.h"
#include "core/geometry/surface_scene.h"
#include "core/mesh/mesh.h"

namespace sagrid::test {

struct ObjectUnderTest {
  Mesh mesh;
  FeatureGrid grid;  // embedded features from 12 views
  std::unique_ptr<SurfaceScene> scene;

  // Computes the features and the scene of `mesh` (z up).
  void finish();
  // An untrained `model`'s automatic count with `extraction` on the field towards `centres`
  // (mesh frame; test::fieldTowards with `offsets`), projected onto the surface.
  ModelPrediction predicted(const std::string& model, const std::vector<Eigen::Vector3f>& centres,
                            const std::vector<float>& offsets,
                            const ExtractionSettings& extraction) const;
};

}  // namespace sagrid::test
