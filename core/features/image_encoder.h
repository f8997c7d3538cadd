// The 2D encoder interface of feature extraction: rendered views in, one feature map per view
// out (per pixel or per patch), to be aggregated into voxels. Backends: the embedded render-
// buffer encoder (embedded_view_encoder.h) and DINOv2 via TorchScript (dinov2_encoder.h).
#pragma once

#include <string>
#include <vector>

#include "core/features/feature_map.h"
#include "core/render/rendered_view.h"
#include "core/render/view_camera.h"

namespace sagrid {

class ImageEncoder {
 public:
  virtual ~ImageEncoder() = default;

  virtual std::string name() const = 0;
  virtual int channels() const = 0;    // per feature-map cell
  virtual int renderSize() const = 0;  // the square view size it expects
  virtual int preferredBatch() const { return 1; }

  // One feature map per view; `cameras` are the views' cameras (same order), for encoders whose
  // features depend on the viewpoint. `out` is resized to views.size().
  virtual void encode(const std::vector<const RenderedView*>& views,
                      const std::vector<const ViewCamera*>& cameras,
                      std::vector<FeatureMap>& out) = 0;
};

}  // namespace sagrid
