#include "ui/render/field_renderer.h"

#include <cmath>
#include <limits>

#include "core/common/error.h"

namespace sagrid::ui {

namespace {
// The +x, +y and +z faces of the unit cube {0,1}^3 (7 distinct corners); voxel.vert mirrors them
// towards the eye, so these are always the visible faces.
const float kCorners[] = {1, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1};
const unsigned kFaceIndices[] = {0, 1, 2, 0, 2, 3,   // +x: (1,0,0) (1,1,0) (1,1,1) (1,0,1)
                                 4, 1, 2, 4, 2, 5,   // +y: (0,1,0) (1,1,0) (1,1,1) (0,1,1)
                                 6, 3, 2, 6, 2, 5};  // +z: (0,0,1) (1,0,1) (1,1,1) (0,1,1)
}  // namespace

FieldRenderer::FieldRenderer() : m_program("voxel.vert", "voxel.frag") {
  m_uViewProj = m_program.uniform("uViewProj");
  m_uEye = m_program.uniform("uEye");
  m_uVoxelSize = m_program.uniform("uVoxelSize");
  m_uThreshold = m_program.uniform("uThreshold");
  m_uMaxDistance = m_program.uniform("uMaxDistance");
  m_uSliceAxis = m_program.uniform("uSliceAxis");
  m_uSlicePosition = m_program.uniform("uSlicePosition");
  m_uOpacity = m_program.uniform("uOpacity");

  m_vao = makeVertexArray();
  m_corners = makeBuffer();
  m_indices = makeBuffer();
  m_instanceBuffer = makeBuffer();
  glBindVertexArray(m_vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, m_corners.id());
  glBufferData(GL_ARRAY_BUFFER, sizeof kCorners, kCorners, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indices.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof kFaceIndices, kFaceIndices, GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, m_instanceBuffer.id());
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glVertexAttribDivisor(1, 1);
  glBindVertexArray(0);
}

void FieldRenderer::upload(const std::vector<DistanceField>& fields, std::uint32_t typeMask) {
  if (fields.size() > 32) throw Error("at most 32 distance fields can be shown at once");
  m_types.clear();
  m_largestDistance = 0.0f;
  m_bounds.setEmpty();
  m_instances4.clear();
  const DistanceField* first = nullptr;
  for (std::size_t f = 0; f < fields.size(); ++f) {
    m_types.push_back(fields[f].type);
    if (!first && ((typeMask >> f) & 1u)) first = &fields[f];
  }
  if (first) {
    // All fields of one object share its grid; the minimum is taken on the dense grid.
    const int n = first->resolution;
    const std::size_t cells = std::size_t(n) * n * n;
    m_nearest.assign(cells, std::numeric_limits<float>::quiet_NaN());
    for (std::size_t f = 0; f < fields.size(); ++f) {
      if (!((typeMask >> f) & 1u) || fields[f].resolution != n) continue;
      const DistanceField& field = fields[f];
      for (std::size_t i = 0; i < field.voxels.size(); ++i) {
        const VoxelIndex& v = field.voxels[i];
        float& slot = m_nearest[(std::size_t(v.i) * n + v.j) * n + v.k];
        if (std::isnan(slot) || field.distances[i] < slot) slot = field.distances[i];
      }
    }
    m_voxelSize = first->voxelSize();
    for (std::size_t linear = 0; linear < cells; ++linear) {
      const float d = m_nearest[linear];
      if (std::isnan(d)) continue;
      const VoxelIndex v{int(linear / (std::size_t(n) * n)), int((linear / n) % n), int(linear % n)};
      const Eigen::Vector3f c = first->normalization.toMesh(voxelCenter(v, n));
      // Unreachable voxels (no point of the shown types) stay drawable as "far".
      if (std::isfinite(d)) m_largestDistance = std::max(m_largestDistance, d);
      m_bounds.extend(c);
      m_instances4.insert(m_instances4.end(), {c.x(), c.y(), c.z(), std::isfinite(d) ? d : 3.0e38f});
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, m_instanceBuffer.id());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m_instances4.size() * sizeof(float)), m_instances4.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  m_instances = m_instances4.size() / 4;
}

void FieldRenderer::draw(const Camera& camera, const FieldSettings& settings) const {
  if (!settings.visible || m_instances == 0) return;
  m_program.use();
  setUniform(m_uViewProj, camera.viewProjection());
  setUniform(m_uEye, camera.eye());
  setUniform(m_uVoxelSize, m_voxelSize);
  const float colorMax = settings.colorMax > 0 ? settings.colorMax : std::max(m_largestDistance, 1e-6f);
  setUniform(m_uMaxDistance, colorMax);
  setUniform(m_uThreshold, settings.threshold > 0 ? settings.threshold : 3.0e38f);
  setUniform(m_uSliceAxis, settings.sliceAxis);
  if (settings.sliceAxis >= 0 && !m_bounds.isEmpty()) {
    const int a = settings.sliceAxis;
    setUniform(m_uSlicePosition, m_bounds.min()[a] + settings.slice * (m_bounds.max()[a] - m_bounds.min()[a]) + 1e-6f);
  }
  setUniform(m_uOpacity, settings.opacity);
  const bool blended = settings.opacity < 0.999f;
  if (blended) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);  // see-through voxels: no sorting, so nothing hides what is behind
  }
  glBindVertexArray(m_vao.id());
  glDrawElementsInstanced(GL_TRIANGLES, 18, GL_UNSIGNED_INT, nullptr, static_cast<GLsizei>(m_instances));
  glBindVertexArray(0);
  if (blended) {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
}

}  // namespace sagrid::ui
