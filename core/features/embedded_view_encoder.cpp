#include "core/features/embedded_view_encoder.h"

#include "core/common/error.h"

namespace sagrid {

void EmbeddedViewEncoder::encodeOne(const RenderedView& view, const ViewCamera& camera,
                                    FeatureMap& out) const {
  out.resize(view.width, view.height, kChannelCount);
  const float fromAbove = camera.position().z() > 0.0f ? 1.0f : 0.0f;
  for (std::size_t p = 0; p < view.pixelCount(); ++p) {
    float* f = &out.values[p * kChannelCount];
    const float m = view.mask[p] ? 1.0f : 0.0f;
    for (int c = 0; c < 3; ++c) {
      f[kAlbedoR + c] = view.albedo[p * 3 + c];  // already 0 on background
      f[kNormalX + c] = view.normal[p * 3 + c];
    }
    f[kMask] = m;
    f[kMaskFromAbove] = m * fromAbove;
  }
}

void EmbeddedViewEncoder::encode(const std::vector<const RenderedView*>& views,
                                 const std::vector<const ViewCamera*>& cameras,
                                 std::vector<FeatureMap>& out) {
  if (views.size() != cameras.size()) throw Error("encode: one camera per view expected");
  out.resize(views.size());
  for (std::size_t i = 0; i < views.size(); ++i) encodeOne(*views[i], *cameras[i], out[i]);
}

}  // namespace sagrid
