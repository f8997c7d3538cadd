#version 330 core
// Affordance point markers: instanced low-poly spheres with a screen-constant radius.
layout(location = 0) in vec3 aUnit;        // unit sphere vertex (also its normal)
layout(location = 1) in vec4 aPoint;       // centre (world), radius (pixels)
layout(location = 2) in vec4 aColor;
uniform mat4 uViewProj;
uniform vec3 uEye;
uniform vec3 uForward;
uniform float uWorldPerPixelPerDepth;  // 2 tan(fov/2) / viewport height
out vec3 vNormal;
out vec4 vColor;
void main() {
  vNormal = aUnit;
  vColor = aColor;
  float depth = max(dot(aPoint.xyz - uEye, uForward), 1e-6);
  float radius = aPoint.w * depth * uWorldPerPixelPerDepth;
  gl_Position = uViewProj * vec4(aPoint.xyz + aUnit * radius, 1.0);
}
