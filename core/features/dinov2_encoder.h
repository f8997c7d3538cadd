// DINOv2 (dinov2_vitl14_reg) as a 2D encoder, loaded from a TorchScript file the user exports
// with packaging/python/export_dinov2.py. Preprocessing as TRELLIS's extract_feature.py: RGB on a
// black background at 518x518, ImageNet mean/std; output the pre-norm patch tokens (registers
// and CLS token dropped), 37x37 patches x 1024 channels per view.
//
// TorchScript contract: forward(x: float32 [B, 3, S, S]) -> float32 [B, (S/14)^2, 1024].
// A file that breaks it fails with ModelError naming the file and the shapes.
#pragma once

#include <filesystem>
#include <memory>

#include "core/features/image_encoder.h"

namespace sagrid {

constexpr int kDinov2InputSize = 518;
constexpr int kDinov2PatchSize = 14;

class Dinov2Encoder : public ImageEncoder {
 public:
  // Throws FileError when the file is missing or not TorchScript. `channels` is what the model
  // must produce (1024 for ViT-L; tests use smaller stand-ins).
  explicit Dinov2Encoder(const std::filesystem::path& modelFile, int inputSize = kDinov2InputSize,
                         int channels = 1024);
  ~Dinov2Encoder() override;

  std::string name() const override { return "dinov2"; }
  int channels() const override { return m_channels; }
  int renderSize() const override { return m_inputSize; }
  int preferredBatch() const override { return 4; }
  int patchGrid() const { return m_inputSize / kDinov2PatchSize; }

  void encode(const std::vector<const RenderedView*>& views,
              const std::vector<const ViewCamera*>& cameras, std::vector<FeatureMap>& out) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
  std::filesystem::path m_file;
  int m_inputSize;
  int m_channels;
};

// ImageNet normalization TRELLIS applies before DINOv2.
constexpr float kImageNetMean[3] = {0.485f, 0.456f, 0.406f};
constexpr float kImageNetStd[3] = {0.229f, 0.224f, 0.225f};

}  // namespace sagrid
