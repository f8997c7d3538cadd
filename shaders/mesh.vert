#version 330 core
// Lit mesh: world-space (z-up) positions; albedo = base colour x vertex colour x texture.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;
layout(location = 3) in vec2 aUv;
uniform mat4 uViewProj;
out vec3 vWorld;
out vec3 vNormal;
out vec3 vColor;
out vec2 vUv;
void main() {
  vWorld = aPosition;
  vNormal = aNormal;
  vColor = aColor;
  vUv = aUv;
  gl_Position = uViewProj * vec4(aPosition, 1.0);
}
