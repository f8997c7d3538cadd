// Draws distance fields as instanced voxel cubes coloured by distance. Each voxel shows the
// distance to the nearest point of the enabled types (the minimum over their fields), so several
// types never fight over the same cube.
//
// Work happens only on change: setFields() combines the fields on the dense grid; when the
// threshold, slice plane or opacity change, the instances are rebuilt on the CPU and uploaded
// once, keeping only the voxels that can be seen — shown, and (when opaque) with at least one
// face not covered by a shown neighbour. A full 64^3 field thus draws its shell (~6 * 64^2
// cubes), not 262,144. Frames with unchanged settings only issue one instanced draw.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "ui/document/distance_field.h"
#include "ui/gl/gl_objects.h"
#include "ui/render/camera.h"
#include "ui/render/shader_program.h"
#include "ui/render/view_settings.h"

namespace sagrid::ui {

class FieldRenderer {
 public:
  FieldRenderer();
  // Combines the fields enabled in `typeMask` (bit i = fields[i]; at most 32).
  void setFields(const std::vector<DistanceField>& fields, std::uint32_t typeMask);
  // Rebuilds the instances if `settings` changed what is visible since the last call.
  void prepare(const FieldSettings& settings);
  void draw(const Camera& camera, const FieldSettings& settings) const;

  std::size_t voxelCount() const { return m_voxelCount; }      // voxels carrying a value
  std::size_t instanceCount() const { return m_instances; }    // cubes drawn now
  float largestDistance() const { return m_largestDistance; }  // finite maximum
  const Eigen::AlignedBox3f& bounds() const { return m_bounds; }
  const std::vector<std::string>& types() const { return m_types; }

 private:
  struct VisibilityKey {
    float threshold = -1, slicePosition = 0;
    int sliceAxis = -2;
    bool cullHidden = false;
    bool operator==(const VisibilityKey& o) const {
      return threshold == o.threshold && slicePosition == o.slicePosition &&
             sliceAxis == o.sliceAxis && cullHidden == o.cullHidden;
    }
  };
  VisibilityKey keyFor(const FieldSettings& settings) const;
  void rebuildInstances(const VisibilityKey& key);

  ShaderProgram m_program;
  GLint m_uViewProj, m_uEye, m_uVoxelSize, m_uMaxDistance, m_uOpacity;
  GlVertexArray m_vao;
  GlBuffer m_corners, m_indices, m_instanceBuffer;
  std::size_t m_instances = 0, m_bufferCapacity = 0, m_voxelCount = 0;
  int m_resolution = 0;
  Normalization m_normalization;
  float m_voxelSize = 0.0f;
  float m_largestDistance = 0.0f;
  Eigen::AlignedBox3f m_bounds;
  std::vector<std::string> m_types;
  std::vector<float> m_nearest;       // dense per-voxel minimum (NaN = no value)
  std::vector<std::uint8_t> m_shown;  // dense, per rebuild
  std::vector<float> m_staging;       // instance data, capacity kept between rebuilds
  VisibilityKey m_key;
};

}  // namespace sagrid::ui
