// Draws distance fields as instanced voxel cubes coloured by distance. Each voxel shows the
// distance to the nearest point of the enabled types (the minimum over their fields), so several
// types never fight over the same cube. Instances are uploaded once per change of the fields or
// of the type toggles; threshold, opacity and slice plane are uniforms, so sliders only redraw.
#pragma once

#include <cstdint>
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
  // Uploads the voxels of the fields enabled in `typeMask` (bit i = fields[i]; at most 32).
  void upload(const std::vector<DistanceField>& fields, std::uint32_t typeMask);
  void draw(const Camera& camera, const FieldSettings& settings) const;

  std::size_t instanceCount() const { return m_instances; }
  float largestDistance() const { return m_largestDistance; }  // finite maximum over all fields
  const Eigen::AlignedBox3f& bounds() const { return m_bounds; }
  const std::vector<std::string>& types() const { return m_types; }

 private:
  ShaderProgram m_program;
  GLint m_uViewProj, m_uEye, m_uVoxelSize, m_uThreshold, m_uMaxDistance, m_uSliceAxis,
      m_uSlicePosition, m_uOpacity;
  GlVertexArray m_vao;
  GlBuffer m_corners, m_indices, m_instanceBuffer;
  std::size_t m_instances = 0;
  float m_voxelSize = 0.0f;
  float m_largestDistance = 0.0f;
  Eigen::AlignedBox3f m_bounds;
  std::vector<std::string> m_types;
  std::vector<float> m_nearest;  // dense per-voxel minimum, reused between uploads
  std::vector<float> m_instances4;
};

}  // namespace sagrid::ui
