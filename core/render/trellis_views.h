// TRELLIS's render protocol (dataset_toolkits/render.py): `count` views on a Hammersley sphere
// with one random offset per object, radius 2, FOV 40 degrees, all looking at the origin of the
// object normalized into [-0.5, 0.5]^3. The offset is drawn from a seed, which callers derive
// from the mesh so an object always gets the same views.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/render/view_camera.h"

namespace sagrid {

constexpr int kTrellisViewCount = 150;
constexpr float kTrellisCameraRadius = 2.0f;
constexpr float kTrellisFovDegrees = 40.0f;

// Radical inverse of n in `base` (van der Corput), as TRELLIS's utils.radical_inverse.
double radicalInverse(int base, std::uint64_t n);

// (yaw, pitch) in radians of sample n of `count` on the sphere, TRELLIS's
// sphere_hammersley_sequence(n, count, offset) without remapping.
Eigen::Vector2f sphereHammersley(int n, int count, const Eigen::Vector2f& offset);

// The per-object offset in [0, 1)^2 drawn from `seed` (TRELLIS uses np.random.rand() twice).
Eigen::Vector2f hammersleyOffset(std::uint64_t seed);

std::vector<ViewCamera> trellisViews(int count, std::uint64_t seed,
                                     float radius = kTrellisCameraRadius,
                                     float fovDegrees = kTrellisFovDegrees);

// A stable 64-bit seed from a text key (the mesh's sha256); FNV-1a.
std::uint64_t seedFromKey(const std::string& key);

// transforms.json as TRELLIS's Blender script writes it ("frames": file_path, camera_angle_x,
// transform_matrix), plus per frame "extrinsics" (OpenCV world->camera) and normalized
// "intrinsics", and the yaw/pitch/radius used.
nlohmann::json camerasToJson(const std::vector<ViewCamera>& views);
std::vector<ViewCamera> camerasFromJson(const nlohmann::json& json);  // throws Error on bad input

}  // namespace sagrid
