// Untrained SAGrid models for tests that exercise the pipeline around a model (annotate,
// retrieval, symmetry averaging), not its accuracy.
#pragma once

#include <string>
#include <vector>

#include "core/features/feature_grid.h"
#include "core/model/affordance_model.h"

namespace sagrid::test {

// A small network whose card matches `grid`'s features (backend, channels, descriptor; the
// descriptor is the category mean, so retrieval finds the grid's own category).
model::AffordanceModel untrainedModelFor(const std::string& name, const FeatureGrid& grid,
                                         unsigned seed = 3);

// A card recording only descriptor statistics (retrieval and classifiers read nothing else);
// `spread` may be empty (cards written before spreads were recorded).
model::AffordanceModel untrainedModelWithDescriptor(const std::string& name,
                                                    std::vector<float> mean,
                                                    std::vector<float> spread);

}  // namespace sagrid::test
