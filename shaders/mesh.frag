#version 330 core
in vec3 vWorld;
in vec3 vNormal;
in vec3 vColor;
in vec2 vUv;
uniform vec3 uEye;
uniform vec3 uBaseColor;
uniform int uHasTexture;
uniform sampler2D uTexture;
uniform int uFlatColor;      // 1: draw uBaseColor unlit (wireframe overlay)
uniform int uPlain;          // 1: one light grey, no texture, material or vertex colour;
                             // 2: uBaseColor alone (a colour per material), no texture or vertex colour;
                             // 3: texture contrast: the texture's uContrast range stretched, nearly unlit
uniform vec2 uContrast;      // the bound texture's luminance range (low, high), linear
uniform float uAlpha;
out vec4 fragColor;
void main() {
  if (uFlatColor == 1) { fragColor = vec4(uBaseColor, uAlpha); return; }
  vec3 albedo = uPlain == 1 ? vec3(0.72) : uPlain == 2 ? uBaseColor : uBaseColor * vColor;
  vec3 texel = uHasTexture == 1 ? texture(uTexture, vec2(vUv.x, 1.0 - vUv.y)).rgb : vec3(1.0);
  if (uPlain == 0) albedo *= texel;
  // Texture contrast: the texture alone, its own range to the full one, brightened as the eye sees
  // it; untextured surfaces stay as modelled.
  bool stretched = uPlain == 3 && uHasTexture == 1;
  if (stretched)
    albedo = pow(clamp((texel - uContrast.x) / max(uContrast.y - uContrast.x, 1e-4), 0.0, 1.0), vec3(1.0 / 2.2));
  vec3 n = normalize(vNormal);
  if (length(vNormal) < 1e-6) n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
  vec3 v = normalize(uEye - vWorld);
  if (dot(n, v) < 0.0) n = -n;  // two-sided: scanned and CAD meshes often have flipped faces
  vec3 key = normalize(v + vec3(0.3, 0.2, 0.6));
  float diffuse = max(dot(n, key), 0.0);
  float hemi = 0.5 + 0.5 * n.z;  // sky above, ground below
  vec3 h = normalize(key + v);
  float spec = pow(max(dot(n, h), 0.0), 32.0) * 0.12;
  vec3 color = stretched ? albedo * (0.8 + 0.2 * diffuse)
                         : albedo * (0.22 + 0.18 * hemi + 0.62 * diffuse) + vec3(spec);
  fragColor = vec4(pow(color, vec3(1.0 / 1.15)), uAlpha);
}
