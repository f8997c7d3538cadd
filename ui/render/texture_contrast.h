// View > Texture contrast (B): marks printed faintly in a texture — a ceramic hob's touch keys and
// zone rings, grey on black glass — are lost under the window's lighting, and neither plain grey
// nor a colour per material shows them (they are in no geometry or material of their own). In this
// view each texture is drawn nearly unlit with its own luminance range stretched to the full one,
// so the faintest marks it holds stand out. Plain data, no GL.
#pragma once

namespace sagrid {
struct Texture;
}

namespace sagrid::ui {

struct LuminanceRange {
  float low = 0.0f, high = 1.0f;  // linear luminance, high > low
};

// The `lowShare` and `highShare` quantiles of the texture's luminance (of at most 65,536 texels
// taken at an even stride), in the linear light the GPU samples an sRGB texture in; widened to at least 1/255 around them for a texture of one colour
// (nothing to stretch), and the whole range for an empty one.
LuminanceRange luminanceRange(const Texture& texture, float lowShare = 0.02f, float highShare = 0.98f);

}  // namespace sagrid::ui
