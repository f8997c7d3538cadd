// The embedded backend's 2D encoder: no network, the render buffers themselves are the per-pixel
// features. Channels: albedo RGB x mask, world normal x mask, mask, mask x (camera above the
// object's centre). Aggregated occlusion-aware, sums divided by the mask sum give the mean
// visible albedo and normal, and the last channel counts views from the upper hemisphere.
#pragma once

#include "core/features/image_encoder.h"

namespace sagrid {

class EmbeddedViewEncoder : public ImageEncoder {
 public:
  enum Channel {
    kAlbedoR = 0,
    kAlbedoG,
    kAlbedoB,
    kNormalX,
    kNormalY,
    kNormalZ,
    kMask,
    kMaskFromAbove,
    kChannelCount
  };

  explicit EmbeddedViewEncoder(int renderSize) : m_renderSize(renderSize) {}

  std::string name() const override { return "embedded"; }
  int channels() const override { return kChannelCount; }
  int renderSize() const override { return m_renderSize; }

  void encode(const std::vector<const RenderedView*>& views,
              const std::vector<const ViewCamera*>& cameras, std::vector<FeatureMap>& out) override;
  void encodeOne(const RenderedView& view, const ViewCamera& camera, FeatureMap& out) const;

 private:
  int m_renderSize;
};

}  // namespace sagrid
