#version 330 core
in vec3 vColor;
in vec3 vWorld;
uniform vec3 uEye;
uniform float uOpacity;
out vec4 fragColor;
void main() {
  vec3 n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));  // flat face normal
  vec3 v = normalize(uEye - vWorld);
  if (dot(n, v) < 0.0) n = -n;
  float shade = 0.55 + 0.45 * abs(dot(n, normalize(v + vec3(0.2, 0.1, 0.5))));
  fragColor = vec4(vColor * shade, uOpacity);
}
