#include "core/generate/parts.h"

#include <algorithm>
#include <cmath>

#include "core/generate/angles.h"

namespace sagrid::gen {

Vec3 jitter(Rng& rng, const Vec3& color, float amount) {
  const float shade = rng.uniformf(-amount, amount);
  Vec3 c = color + Vec3::Constant(shade);
  for (int i = 0; i < 3; ++i) c[i] += rng.uniformf(-amount, amount) * 0.4f;
  return c.cwiseMax(0.0f).cwiseMin(1.0f);
}

Finish finishNamed(Rng& rng, const std::string& name) {
  if (name == "stainless") return {name, jitter(rng, {0.72f, 0.73f, 0.74f}, 0.08f)};
  if (name == "black_glass") return {name, jitter(rng, {0.06f, 0.06f, 0.07f}, 0.04f)};
  if (name == "white_enamel") return {name, jitter(rng, {0.92f, 0.92f, 0.9f}, 0.05f)};
  if (name == "cast_iron") return {name, jitter(rng, {0.16f, 0.16f, 0.16f}, 0.05f)};
  if (name == "dark_grey") return {name, jitter(rng, {0.3f, 0.3f, 0.32f}, 0.06f)};
  if (name == "chrome") return {name, jitter(rng, {0.8f, 0.81f, 0.83f}, 0.06f)};
  if (name == "brushed_nickel") return {name, jitter(rng, {0.66f, 0.63f, 0.58f}, 0.05f)};
  if (name == "matte_black") return {name, jitter(rng, {0.08f, 0.08f, 0.08f}, 0.03f)};
  if (name == "brass") return {name, jitter(rng, {0.78f, 0.62f, 0.3f}, 0.05f)};
  if (name == "ceramic_white") return {name, jitter(rng, {0.95f, 0.95f, 0.95f}, 0.03f)};
  if (name == "granite") return {name, jitter(rng, {0.35f, 0.33f, 0.32f}, 0.12f)};
  if (name == "wood") return {name, jitter(rng, {0.55f, 0.4f, 0.26f}, 0.1f)};
  if (name == "laminate") return {name, jitter(rng, {0.85f, 0.83f, 0.78f}, 0.1f)};
  if (name == "retro_red") return {name, jitter(rng, {0.7f, 0.12f, 0.1f}, 0.06f)};
  if (name == "cream") return {name, jitter(rng, {0.93f, 0.88f, 0.72f}, 0.04f)};
  if (name == "pastel_blue") return {name, jitter(rng, {0.55f, 0.7f, 0.8f}, 0.06f)};
  if (name == "red") return {name, jitter(rng, {0.6f, 0.1f, 0.1f}, 0.08f)};
  if (name == "blue") return {name, jitter(rng, {0.15f, 0.3f, 0.7f}, 0.08f)};
  return {name, jitter(rng, {0.5f, 0.5f, 0.5f}, 0.2f)};
}

Finish pickFinish(Rng& rng, const std::vector<std::string>& names) {
  return finishNamed(rng, rng.pick(names));
}

const char* toString(KnobStyle style) {
  switch (style) {
    case KnobStyle::Cylinder: return "cylinder";
    case KnobStyle::GripBar: return "grip_bar";
    case KnobStyle::Skirted: return "skirted";
    case KnobStyle::Dome: return "dome";
    case KnobStyle::Pointer: return "pointer";
    case KnobStyle::Fluted: return "fluted";
    case KnobStyle::Chunky: return "chunky";
  }
  return "cylinder";
}

KnobStyle pickKnobStyle(Rng& rng) {
  return static_cast<KnobStyle>(rng.weighted({1.0, 1.5, 1.2, 0.8, 0.8, 0.8, 0.5}));
}

KnobShape randomKnob(Rng& rng, float sizeScale) {
  KnobShape k;
  k.style = pickKnobStyle(rng);
  k.radius = rng.uniformf(0.012, 0.024) * sizeScale;
  k.depth = rng.uniformf(0.012, 0.028) * sizeScale;
  if (k.style == KnobStyle::Chunky) {
    k.radius = rng.uniformf(0.022, 0.04) * sizeScale;
    k.depth = rng.uniformf(0.025, 0.05) * sizeScale;
  }
  k.segments = rng.pick(std::vector<int>{10, 16, 24, 32, 48});
  if (k.style == KnobStyle::Fluted) k.segments = rng.pick(std::vector<int>{8, 10, 12, 16});
  return k;
}

Vec3 buildKnob(ShapeBuilder& b, const Affine& frame, const KnobShape& k, int material,
               int accent) {
  const float r = k.radius, d = k.depth;
  switch (k.style) {
    case KnobStyle::Cylinder:
      b.lathe(frame, {{0, 0}, {r, 0}, {r, d * 0.9f}, {r * 0.9f, d}, {0, d}}, k.segments, material);
      break;
    case KnobStyle::GripBar: {
      b.lathe(frame, {{0, 0}, {r, 0}, {r, d * 0.45f}, {0, d * 0.45f}}, k.segments, material);
      // The grip bar across the face is what a hand turns.
      b.box(frame * translation(0, 0, d * 0.72f), Vec3(r * 1.9f, r * 0.45f, d * 0.55f), material,
            r * 0.08f, 1);
      b.box(frame * translation(r * 0.6f, 0, d * 0.46f), Vec3(r * 0.3f, r * 0.08f, 0.002f), accent);
      break;
    }
    case KnobStyle::Skirted:
      b.lathe(frame, {{0, 0}, {r * 1.35f, 0}, {r * 1.3f, d * 0.18f}, {r * 0.75f, d * 0.3f},
                      {r * 0.7f, d}, {0, d}},
              k.segments, material);
      break;
    case KnobStyle::Dome:
      b.lathe(frame, {{0, 0}, {r, 0}, {r, d * 0.35f}, {r * 0.85f, d * 0.75f}, {r * 0.5f, d * 0.95f},
                      {0, d}},
              k.segments, material);
      break;
    case KnobStyle::Pointer: {
      b.lathe(frame, {{0, 0}, {r, 0}, {r, d * 0.3f}, {0, d * 0.3f}}, k.segments, material);
      // A tapered pointer fin.
      b.box(frame * translation(r * 0.25f, 0, d * 0.65f), Vec3(r * 1.5f, r * 0.5f, d * 0.7f),
            material, r * 0.1f, 1);
      break;
    }
    case KnobStyle::Fluted:
      b.lathe(frame, {{0, 0}, {r * 1.05f, 0}, {r, d * 0.9f}, {r * 0.8f, d}, {0, d}}, k.segments,
              material);
      b.lathe(frame, {{0, d}, {r * 0.45f, d}, {r * 0.45f, d + 0.0015f}, {0, d + 0.0015f}}, 16,
              accent);
      break;
    case KnobStyle::Chunky:
      b.box(frame * translation(0, 0, d * 0.5f), Vec3(2 * r, 2 * r, d), material, r * 0.25f, 2);
      b.box(frame * translation(0, 0, d + 0.004f), Vec3(r * 1.8f, r * 0.5f, 0.008f), accent,
            0.002f, 1);
      break;
  }
  return frame * Vec3(0, 0, d * 0.5f);
}

void buildBarHandle(ShapeBuilder& b, const Affine& frame, float length, float standoff,
                    float radius, int material) {
  const float half = 0.5f * length;
  const int sides = 12;
  std::vector<Vec3> path = {frame * Vec3(-half, 0, 0), frame * Vec3(-half, 0, standoff),
                            frame * Vec3(half, 0, standoff), frame * Vec3(half, 0, 0)};
  // Rounded posts: a short bend at each corner keeps the tube from pinching.
  std::vector<Vec3> smooth;
  smooth.push_back(path[0]);
  const float bend = std::min(standoff * 0.4f, radius * 2.0f);
  smooth.push_back(frame * Vec3(-half, 0, standoff - bend));
  smooth.push_back(frame * Vec3(-half + bend * 0.3f, 0, standoff - bend * 0.3f));
  smooth.push_back(frame * Vec3(-half + bend, 0, standoff));
  smooth.push_back(frame * Vec3(half - bend, 0, standoff));
  smooth.push_back(frame * Vec3(half - bend * 0.3f, 0, standoff - bend * 0.3f));
  smooth.push_back(frame * Vec3(half, 0, standoff - bend));
  smooth.push_back(path[3]);
  b.tube(smooth, radius, sides, material);
}

}  // namespace sagrid::gen
