#include "support/point_scorers.h"

namespace sagrid::test {

ModelPointScorer fieldOnlyScorer(float bias) {
  ModelPointScorer s;
  const std::size_t d = candidateFeatureNames().size();
  s.classifier.mean.assign(d, 0);
  s.classifier.scale.assign(d, 1);
  s.classifier.weights.assign(d, 0);
  s.classifier.weights[0] = -1;  // feature 0 is the field's distance: nearer is better
  s.classifier.bias = bias;
  s.choice = {0.5f, 0.5f, 0.08f};
  return s;
}

}  // namespace sagrid::test
