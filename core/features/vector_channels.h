// Which per-voxel feature channels are 3-vectors in the normalized frame (e.g. the embedded
// backend's normal_x/normal_y/normal_z): training augmentation rotates and reflects them with the
// voxel grid. Derived from the channel names (featureChannelNames): three consecutive channels
// "<base>_x", "<base>_y", "<base>_z". Backends whose channels are not geometric vectors (DINOv2
// patch features, TRELLIS latents) have none.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace sagrid {

std::vector<std::array<int, 3>> vectorChannelTriples(const std::vector<std::string>& channelNames);

}  // namespace sagrid
