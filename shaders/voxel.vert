#version 330 core
// Instanced voxel cubes of a distance field. Per cube only the three faces that can face the
// camera exist (12 corners, 18 indices; the offsets are mirrored per instance towards the eye),
// and of those only the faces whose neighbour voxel is not shown (aExposed bits, computed on the
// CPU per change) are kept: covered faces collapse to a point, so a dense block costs its surface.
layout(location = 0) in vec3 aCorner;      // in {0,1}^3 on the +x, +y or +z face
layout(location = 1) in float aAxis;       // which face: 0 = x, 1 = y, 2 = z
layout(location = 2) in vec4 aVoxel;       // centre (world), distance to the nearest shown type
layout(location = 3) in float aExposed;    // bits +x,-x,+y,-y,+z,-z: neighbour not shown
uniform mat4 uViewProj;
uniform vec3 uEye;
uniform float uVoxelSize;
uniform float uMaxDistance;   // colour scale
out vec3 vColor;
out vec2 vFaceUv;
flat out int vAxis;
#include "colormap.glsl"
void main() {
  int axis = int(aAxis + 0.5);
  vec3 towardsEye = sign(uEye - aVoxel.xyz);
  towardsEye = mix(vec3(1.0), towardsEye, abs(towardsEye));
  int bit = axis * 2 + (towardsEye[axis] > 0.0 ? 0 : 1);
  if (((int(aExposed + 0.5) >> bit) & 1) == 0) { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); return; }
  vec3 world = aVoxel.xyz + (aCorner - 0.5) * towardsEye * uVoxelSize;
  vColor = distanceColor(aVoxel.w, uMaxDistance);
  vFaceUv = axis == 0 ? aCorner.yz : (axis == 1 ? aCorner.xz : aCorner.xy);
  vAxis = axis;
  gl_Position = uViewProj * vec4(world, 1.0);
}
