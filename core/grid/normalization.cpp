#include "core/grid/normalization.h"

#include <cmath>

#include "core/common/error.h"
#include "core/mesh/mesh.h"

namespace sagrid {

Normalization Normalization::fromBounds(const Eigen::AlignedBox3f& box) {
  if (auto problem = normalizationProblem(box)) throw Error("mesh " + *problem);
  Normalization n;
  n.center = box.center();
  n.scale = 1.0f / (box.max() - box.min()).maxCoeff();
  return n;
}

Normalization Normalization::fromMesh(const Mesh& mesh) { return fromBounds(mesh.bounds()); }

Mesh normalizedCopy(const Mesh& mesh, const Normalization& normalization) {
  Mesh copy = mesh;
  for (auto& p : copy.positions) p = normalization.toNormalized(p);
  return copy;
}

}  // namespace sagrid
