#include "core/training/augmentation.h"

#include <cmath>
#include <map>

namespace sagrid {
namespace {

constexpr float kTwoPi = 6.28318530718f;

// The rigid part (rotation, then reflections) on x and y; z is unchanged.
Eigen::Vector3f rotateFlip(Eigen::Vector3f p, const Augmentation& a) {
  for (int t = 0; t < ((a.quarterTurns % 4) + 4) % 4; ++t)
    p = Eigen::Vector3f(-p.y(), p.x(), p.z());
  if (a.flipX) p.x() = -p.x();
  if (a.flipY) p.y() = -p.y();
  return p;
}

Eigen::Vector3f transformPoint(const Eigen::Vector3f& p, const Augmentation& a, int resolution) {
  return rotateFlip(a.warpPoint(p), a) + a.shift.cast<float>() / static_cast<float>(resolution);
}

}  // namespace

Eigen::Vector3f Augmentation::warpPoint(const Eigen::Vector3f& p) const {
  Eigen::Vector3f q = p;
  for (const auto& w : warp) q += w.amplitude * std::sin(kTwoPi * w.frequency.dot(p) + w.phase);
  return q;
}

Augmentation randomAugmentation(const TrainingSample& s, const AugmentationRanges& ranges,
                                std::mt19937& rng) {
  Augmentation a;
  std::uniform_int_distribution<int> turns(0, 3);
  std::bernoulli_distribution coin(0.5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  if (ranges.rotate) a.quarterTurns = turns(rng);
  if (ranges.reflect) {
    a.flipX = coin(rng);
    a.flipY = coin(rng);
  }
  if (ranges.warpVoxels > 0 && ranges.warpWaves > 0) {
    // Amplitudes split over the waves; frequencies up to 1.5 cycles per unit keep the warp's
    // gradient (2 pi f A) far below 1, so it stays a smooth, invertible deformation.
    const float amplitude =
        ranges.warpVoxels / static_cast<float>(s.resolution) / static_cast<float>(ranges.warpWaves);
    for (int m = 0; m < ranges.warpWaves; ++m) {
      Augmentation::WarpWave w;
      w.amplitude = Eigen::Vector3f(unit(rng), unit(rng), unit(rng)) * amplitude;
      w.frequency = Eigen::Vector3f(unit(rng), unit(rng), unit(rng)) * 1.5f;
      w.phase = unit(rng) * kTwoPi / 2;
      a.warp.push_back(w);
    }
  }
  if (ranges.translate && !s.voxels.empty()) {
    Augmentation rigid = a;
    rigid.warp.clear();
    Eigen::Vector3i lo = Eigen::Vector3i::Constant(s.resolution),
                    hi = Eigen::Vector3i::Constant(-1);
    for (const auto& v : s.voxels) {
      const Eigen::Vector3f p = rotateFlip(voxelCenter(v, s.resolution), rigid);
      const VoxelIndex q = voxelContaining(p, s.resolution);
      lo = lo.cwiseMin(Eigen::Vector3i(q.i, q.j, q.k));
      hi = hi.cwiseMax(Eigen::Vector3i(q.i, q.j, q.k));
    }
    for (int axis = 0; axis < 3; ++axis) {
      const int low = std::max(-4, -lo[axis]);
      const int high = std::min(4, s.resolution - 1 - hi[axis]);
      a.shift[axis] = low < high ? std::uniform_int_distribution<int>(low, high)(rng) : 0;
    }
  }
  return a;
}

TrainingSample augment(const TrainingSample& s, const Augmentation& a,
                       const std::vector<std::array<int, 3>>& vectorChannels) {
  TrainingSample out;
  out.id = s.id;
  out.resolution = s.resolution;
  out.channels = s.channels;
  out.descriptor = s.descriptor;
  const int r = s.resolution;
  const float n = static_cast<float>(r);
  const std::size_t c = static_cast<std::size_t>(s.channels);

  // Linear index -> (feature sum, count); std::map keeps the output in increasing order.
  std::map<std::size_t, std::pair<std::vector<float>, int>> cells;
  for (std::size_t v = 0; v < s.voxels.size(); ++v) {
    const Eigen::Vector3f p = transformPoint(voxelCenter(s.voxels[v], r), a, r);
    const Eigen::Vector3f g = (p.array() + 0.5f) * n;
    const int i = static_cast<int>(std::floor(g.x())), j = static_cast<int>(std::floor(g.y())),
              k = static_cast<int>(std::floor(g.z()));
    if (i < 0 || j < 0 || k < 0 || i >= r || j >= r || k >= r) continue;  // warped off the grid
    const std::size_t linear = (static_cast<std::size_t>(i) * r + j) * r + k;
    auto& cell = cells[linear];
    if (cell.first.empty()) cell.first.assign(c, 0.0f);
    const float* f = s.features.data() + v * c;
    for (std::size_t ch = 0; ch < c; ++ch) cell.first[ch] += f[ch];
    cell.second += 1;
  }
  Augmentation rigid = a;
  rigid.warp.clear();
  out.voxels.reserve(cells.size());
  out.features.reserve(cells.size() * c);
  for (auto& [linear, cell] : cells) {
    const int i = static_cast<int>(linear / (static_cast<std::size_t>(r) * r));
    const int j = static_cast<int>((linear / r) % r);
    const int k = static_cast<int>(linear % r);
    out.voxels.push_back({i, j, k});
    for (auto& value : cell.first) value /= static_cast<float>(cell.second);
    for (const auto& t : vectorChannels) {
      Eigen::Vector3f vec(cell.first[t[0]], cell.first[t[1]], cell.first[t[2]]);
      const float length = vec.norm();
      vec = rotateFlip(vec, rigid);
      if (cell.second > 1 && length > 1e-6f) vec /= length;  // averaged unit normals
      cell.first[t[0]] = vec.x();
      cell.first[t[1]] = vec.y();
      cell.first[t[2]] = vec.z();
    }
    out.features.insert(out.features.end(), cell.first.begin(), cell.first.end());
  }
  for (const auto& t : s.targets) out.targets.push_back(transformPoint(t, a, r));
  return out;
}

}  // namespace sagrid
