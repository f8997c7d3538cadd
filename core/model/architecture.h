// The SAGrid CNN architecture in the paper's Table I notation: a comma-separated list of conv
// layers "[kernel,padding,out_channels(,dilation)]", e.g. "[3,1,1024],[3,4,512,4],[3,1,256]".
// Every layer keeps the grid size (padding = dilation * (kernel - 1) / 2), because the network
// predicts one distance per voxel; a 1x1x1 head with Softplus follows the last layer.
#pragma once

#include <string>
#include <vector>

namespace sagrid::model {

struct ConvLayerSpec {
  int kernel = 3;
  int padding = 1;
  int outChannels = 16;
  int dilation = 1;
  bool operator==(const ConvLayerSpec& o) const {
    return kernel == o.kernel && padding == o.padding && outChannels == o.outChannels &&
           dilation == o.dilation;
  }
};

// How the same architecture (and the same weights) is executed.
enum class ExecutionMode {
  Sparse,  // submanifold sparse convolution over occupied voxels only (default; CPU-friendly)
  Dense,   // plain Conv3d over the whole grid, as in the paper (GPU or comparison)
};
const char* toString(ExecutionMode mode);
ExecutionMode parseExecutionMode(const std::string& text);  // "sparse" | "dense"

struct Architecture {
  std::vector<ConvLayerSpec> layers;

  // Throws InvalidArgument naming the layer and the problem.
  static Architecture parse(const std::string& text);
  std::string toString() const;  // canonical Table I form; dilation written only when != 1
  // Largest distance (voxels, per axis) from which a voxel's output can see input.
  int receptiveRadius() const;
};

// The architecture the shipped models use: dilations for a receptive field of 8 voxels (the
// paper's CNN-1 has 7) at 16 channels, 0.44 GMAC per forward pass on a 15k-voxel object (the
// 32-channel variant needs 1.31 GMAC and gets a third of the epochs in the 15-minute CPU budget).
inline constexpr const char* kDefaultArchitecture = "[3,1,16],[3,2,16,2],[3,4,16,4],[3,1,16]";
// The paper's best architecture (Table I, CNN-1), for comparison.
inline constexpr const char* kPaperCnn1Architecture = "[3,1,1024],[3,4,512,4],[3,1,256],[3,1,128]";

}  // namespace sagrid::model
