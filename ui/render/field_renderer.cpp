#include "ui/render/field_renderer.h"

#include <cmath>
#include <limits>

#include "core/common/error.h"

namespace sagrid::ui {

namespace {
// The +x, +y and +z faces of the unit cube {0,1}^3, four corners each (x, y, z, face axis);
// voxel.vert mirrors them towards the eye, so these are always the faces that can be seen.
const float kCorners[] = {1, 0, 0, 0, 1, 1, 0, 0, 1, 1, 1, 0, 1, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 1,
                          1, 1, 1, 1, 0, 1, 1, 1, 0, 0, 1, 2, 1, 0, 1, 2, 1, 1, 1, 2, 0, 1, 1, 2};
const unsigned kFaceIndices[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 8, 9, 10, 8, 10, 11};
constexpr std::size_t kFloatsPerInstance = 5;  // centre xyz, distance, exposed-face bits
}  // namespace

FieldRenderer::FieldRenderer() : m_program("voxel.vert", "voxel.frag") {
  m_uViewProj = m_program.uniform("uViewProj");
  m_uEye = m_program.uniform("uEye");
  m_uVoxelSize = m_program.uniform("uVoxelSize");
  m_uMaxDistance = m_program.uniform("uMaxDistance");
  m_uOpacity = m_program.uniform("uOpacity");

  m_vao = makeVertexArray();
  m_corners = makeBuffer();
  m_indices = makeBuffer();
  m_instanceBuffer = makeBuffer();
  glBindVertexArray(m_vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, m_corners.id());
  glBufferData(GL_ARRAY_BUFFER, sizeof kCorners, kCorners, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 4 * sizeof(float),
                        reinterpret_cast<void*>(3 * sizeof(float)));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indices.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof kFaceIndices, kFaceIndices, GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, m_instanceBuffer.id());
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, kFloatsPerInstance * sizeof(float), nullptr);
  glVertexAttribDivisor(2, 1);
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, kFloatsPerInstance * sizeof(float),
                        reinterpret_cast<void*>(4 * sizeof(float)));
  glVertexAttribDivisor(3, 1);
  glBindVertexArray(0);
}

void FieldRenderer::setFields(const std::vector<DistanceField>& fields, std::uint32_t typeMask) {
  if (fields.size() > 32) throw Error("at most 32 distance fields can be shown at once");
  m_types.clear();
  m_largestDistance = 0.0f;
  m_bounds.setEmpty();
  m_voxelCount = 0;
  m_resolution = 0;
  const DistanceField* first = nullptr;
  for (std::size_t f = 0; f < fields.size(); ++f) {
    m_types.push_back(fields[f].type);
    if (!first && ((typeMask >> f) & 1u)) first = &fields[f];
  }
  if (first) {
    // All fields of one object share its grid; the minimum is taken on the dense grid.
    const int n = first->resolution;
    m_resolution = n;
    m_normalization = first->normalization;
    m_voxelSize = first->voxelSize();
    m_nearest.assign(std::size_t(n) * n * n, std::numeric_limits<float>::quiet_NaN());
    for (std::size_t f = 0; f < fields.size(); ++f) {
      if (!((typeMask >> f) & 1u) || fields[f].resolution != n) continue;
      const DistanceField& field = fields[f];
      for (std::size_t i = 0; i < field.voxels.size(); ++i) {
        const VoxelIndex& v = field.voxels[i];
        float& slot = m_nearest[(std::size_t(v.i) * n + v.j) * n + v.k];
        if (std::isnan(slot) || field.distances[i] < slot) slot = field.distances[i];
      }
    }
    for (float d : m_nearest) {
      if (std::isnan(d)) continue;
      ++m_voxelCount;
      if (std::isfinite(d)) m_largestDistance = std::max(m_largestDistance, d);
    }
    const Eigen::Vector3f half = Eigen::Vector3f::Constant(0.5f);
    m_bounds.extend(m_normalization.toMesh(-half));
    m_bounds.extend(m_normalization.toMesh(half));
  } else {
    m_nearest.clear();
  }
  m_key = VisibilityKey{};  // forces a rebuild on the next prepare()
}

FieldRenderer::VisibilityKey FieldRenderer::keyFor(const FieldSettings& settings) const {
  VisibilityKey key;
  key.threshold =
      settings.threshold > 0 ? settings.threshold : std::numeric_limits<float>::infinity();
  key.sliceAxis = settings.sliceAxis;
  if (settings.sliceAxis >= 0 && !m_bounds.isEmpty()) {
    const int a = settings.sliceAxis;
    key.slicePosition =
        m_bounds.min()[a] + settings.slice * (m_bounds.max()[a] - m_bounds.min()[a]);
  }
  // Hidden voxels matter only when one can see through the shown ones.
  key.cullHidden = settings.opacity >= 0.999f;
  return key;
}

void FieldRenderer::prepare(const FieldSettings& settings) {
  if (!settings.visible) return;
  const VisibilityKey key = keyFor(settings);
  if (key == m_key) return;
  rebuildInstances(key);
  m_key = key;
}

void FieldRenderer::rebuildInstances(const VisibilityKey& key) {
  m_staging.clear();
  const int n = m_resolution;
  if (n > 0) {
    const std::size_t cells = std::size_t(n) * n * n;
    m_shown.assign(cells, 0);
    for (std::size_t linear = 0; linear < cells; ++linear) {
      const float d = m_nearest[linear];
      if (std::isnan(d) || !(d <= key.threshold || (std::isinf(key.threshold) && std::isinf(d))))
        continue;
      if (key.sliceAxis >= 0) {
        const VoxelIndex v{int(linear / (std::size_t(n) * n)), int((linear / n) % n),
                           int(linear % n)};
        const Eigen::Vector3f c = m_normalization.toMesh(voxelCenter(v, n));
        if (c[key.sliceAxis] > key.slicePosition) continue;
      }
      m_shown[linear] = 1;
    }
    auto shownAt = [&](int i, int j, int k) {
      return i >= 0 && j >= 0 && k >= 0 && i < n && j < n && k < n &&
             m_shown[(std::size_t(i) * n + j) * n + k];
    };
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        for (int k = 0; k < n; ++k) {
          const std::size_t linear = (std::size_t(i) * n + j) * n + k;
          if (!m_shown[linear]) continue;
          // A face next to a shown voxel is covered while opaque; see-through shows them all.
          int exposed = 63;
          if (key.cullHidden) {
            exposed = (!shownAt(i + 1, j, k) << 0) | (!shownAt(i - 1, j, k) << 1) |
                      (!shownAt(i, j + 1, k) << 2) | (!shownAt(i, j - 1, k) << 3) |
                      (!shownAt(i, j, k + 1) << 4) | (!shownAt(i, j, k - 1) << 5);
            if (exposed == 0) continue;  // inside: never visible
          }
          const Eigen::Vector3f c = m_normalization.toMesh(voxelCenter({i, j, k}, n));
          const float d = m_nearest[linear];
          m_staging.insert(m_staging.end(),
                           {c.x(), c.y(), c.z(), std::isfinite(d) ? d : 3.0e38f, float(exposed)});
        }
      }
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, m_instanceBuffer.id());
  const std::size_t bytes = m_staging.size() * sizeof(float);
  if (bytes > m_bufferCapacity) {
    m_bufferCapacity = bytes;
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(bytes), m_staging.data(), GL_DYNAMIC_DRAW);
  } else if (bytes > 0) {
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(bytes), m_staging.data());
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  m_instances = m_staging.size() / kFloatsPerInstance;
}

void FieldRenderer::draw(const Camera& camera, const FieldSettings& settings) const {
  if (!settings.visible || m_instances == 0) return;
  m_program.use();
  setUniform(m_uViewProj, camera.viewProjection());
  setUniform(m_uEye, camera.eye());
  setUniform(m_uVoxelSize, m_voxelSize);
  const float colorMax =
      settings.colorMax > 0 ? settings.colorMax : std::max(m_largestDistance, 1e-6f);
  setUniform(m_uMaxDistance, colorMax);
  setUniform(m_uOpacity, settings.opacity);
  const bool blended = settings.opacity < 0.999f;
  if (blended) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);  // see-through voxels: no sorting, so nothing hides what is behind
  }
  glBindVertexArray(m_vao.id());
  glDrawElementsInstanced(GL_TRIANGLES, 18, GL_UNSIGNED_INT, nullptr,
                          static_cast<GLsizei>(m_instances));
  glBindVertexArray(0);
  if (blended) {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
}

}  // namespace sagrid::ui
