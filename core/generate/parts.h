// Parts shared by the stove and sink generators: finishes (colour palettes), control knobs,
// bar handles and feet. Each part is built into a ShapeBuilder in the frame it is given.
#pragma once

#include <string>

#include "core/generate/random.h"
#include "core/generate/shape_builder.h"

namespace sagrid::gen {

// A named surface finish with a jittered colour, e.g. "stainless", "black_glass".
struct Finish {
  std::string name;
  Vec3 color;
};
Finish pickFinish(Rng& rng, const std::vector<std::string>& names);
Finish finishNamed(Rng& rng, const std::string& name);
Vec3 jitter(Rng& rng, const Vec3& color, float amount);

enum class KnobStyle { Cylinder, GripBar, Skirted, Dome, Pointer, Fluted, Chunky };
const char* toString(KnobStyle style);
KnobStyle pickKnobStyle(Rng& rng);

struct KnobShape {
  KnobStyle style = KnobStyle::GripBar;
  float radius = 0.02f;
  float depth = 0.02f;   // how far it stands off its mounting surface
  int segments = 24;
};
KnobShape randomKnob(Rng& rng, float sizeScale);

// Builds a knob whose axis is the frame's local +z, standing on the local z = 0 plane.
// Returns the centre of its grip (local (0, 0, depth / 2) in the object frame).
Vec3 buildKnob(ShapeBuilder& builder, const Affine& frame, const KnobShape& knob, int material,
               int accentMaterial);

// A bar handle (towel-bar style) along local x of the given length, standing off local z = 0
// towards +z by `standoff`.
void buildBarHandle(ShapeBuilder& builder, const Affine& frame, float length, float standoff,
                    float radius, int material);

}  // namespace sagrid::gen
