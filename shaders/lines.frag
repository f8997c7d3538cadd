#version 330 core
in vec4 vColor;
in vec3 vWorld;
uniform vec3 uFadeCenter;
uniform float uFadeRadius;  // lines fade out towards the edge of the grid
out vec4 fragColor;
void main() {
  float fade = 1.0 - smoothstep(0.6 * uFadeRadius, uFadeRadius, length(vWorld.xy - uFadeCenter.xy));
  fragColor = vec4(vColor.rgb, vColor.a * fade);
}
