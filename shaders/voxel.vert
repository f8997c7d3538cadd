#version 330 core
// Instanced voxel cubes of a distance field. Only the three faces that can face the camera are
// drawn (7 corners, 18 indices): the corner offsets are mirrored per instance towards the eye.
// Threshold, slice plane and opacity are uniforms, so moving a slider never re-uploads instances.
layout(location = 0) in vec3 aCorner;      // in {0,1}^3, the +x/+y/+z faces
layout(location = 1) in vec4 aVoxel;       // centre (world), distance to the nearest shown type
uniform mat4 uViewProj;
uniform vec3 uEye;
uniform float uVoxelSize;
uniform float uThreshold;     // show voxels closer than this
uniform float uMaxDistance;   // colour scale
uniform int uSliceAxis;       // -1 none, 0/1/2 = x/y/z: keep voxels at or below uSlicePosition
uniform float uSlicePosition;
out vec3 vColor;
out vec3 vWorld;
#include "colormap.glsl"
void main() {
  bool visible = aVoxel.w <= uThreshold;
  if (uSliceAxis >= 0) visible = visible && aVoxel[uSliceAxis] <= uSlicePosition;
  if (!visible) { gl_Position = vec4(0.0, 0.0, 2.0, 1.0); return; }  // clipped away
  vec3 towardsEye = sign(uEye - aVoxel.xyz);
  towardsEye = mix(vec3(1.0), towardsEye, abs(towardsEye));
  vec3 world = aVoxel.xyz + (aCorner - 0.5) * towardsEye * uVoxelSize * 0.92;
  vColor = distanceColor(aVoxel.w, uMaxDistance);
  vWorld = world;
  gl_Position = uViewProj * vec4(world, 1.0);
}
