#version 330 core
in vec3 vNormal;
in vec4 vColor;
uniform vec3 uViewDir;  // from eye towards the target
uniform float uAlpha;   // < 1 for the "seen through the mesh" pass
out vec4 fragColor;
void main() {
  float facing = max(dot(normalize(vNormal), -uViewDir), 0.0);
  vec3 color = vColor.rgb * (0.45 + 0.55 * facing) + vec3(0.25) * pow(facing, 24.0);
  fragColor = vec4(color, vColor.a * uAlpha);
}
