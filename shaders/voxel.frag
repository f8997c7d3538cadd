#version 330 core
in vec3 vColor;
in vec2 vFaceUv;
flat in int vAxis;
uniform vec3 uEye;
uniform float uOpacity;
out vec4 fragColor;
void main() {
  // Fixed shade per face direction (top brightest) and a thin dark rim, so single voxels read
  // as cubes without gaps between them.
  float shade = vAxis == 2 ? 1.0 : (vAxis == 0 ? 0.82 : 0.68);
  vec2 edge = min(vFaceUv, 1.0 - vFaceUv);
  float rim = smoothstep(0.0, 0.09, min(edge.x, edge.y));
  fragColor = vec4(vColor * shade * mix(0.72, 1.0, rim), uOpacity);
}
