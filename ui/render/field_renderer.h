// Draws distance fields as instanced voxel cubes coloured by distance. Instances (centre,
// distance, field index) are uploaded once per change of the fields; threshold, opacity, slice
// plane and per-type toggles are uniforms, so the frame loop only draws.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "ui/document/distance_field.h"
#include "ui/gl/gl_objects.h"
#include "ui/render/camera.h"
#include "ui/render/shader_program.h"
#include "ui/render/view_settings.h"

namespace sagrid::ui {

class FieldRenderer {
 public:
  FieldRenderer();
  // Uploads all voxels of all fields (at most 32 fields: one toggle bit each).
  void upload(const std::vector<DistanceField>& fields);
  void draw(const Camera& camera, const FieldSettings& settings) const;

  std::size_t instanceCount() const { return m_instances; }
  float largestDistance() const { return m_largestDistance; }  // finite maximum over all fields
  const Eigen::AlignedBox3f& bounds() const { return m_bounds; }
  const std::vector<std::string>& types() const { return m_types; }

 private:
  ShaderProgram m_program;
  GLint m_uViewProj, m_uEye, m_uVoxelSize, m_uThreshold, m_uMaxDistance, m_uTypeMask, m_uSliceAxis,
      m_uSlicePosition, m_uOpacity;
  GlVertexArray m_vao;
  GlBuffer m_corners, m_indices, m_instanceBuffer;
  std::size_t m_instances = 0;
  float m_voxelSize = 0.0f;
  float m_largestDistance = 0.0f;
  Eigen::AlignedBox3f m_bounds;
  std::vector<std::string> m_types;
};

}  // namespace sagrid::ui
