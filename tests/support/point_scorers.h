// Hand-made learned point decisions for tests: a logistic regression that reads only the field's
// distance, so what it chooses is known without training.
#pragma once

#include "core/annotate/point_scorer.h"

namespace sagrid::test {

// Probability sigmoid(bias - distance): with a bias of -10 no candidate reaches the thresholds
// (0.5) and the best one alone is taken; with +10 every candidate does.
ModelPointScorer fieldOnlyScorer(float bias);

}  // namespace sagrid::test
