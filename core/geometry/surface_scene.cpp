#include "core/geometry/surface_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>

#include <embree3/rtcore.h>

#include "core/common/error.h"
#include "core/geometry/closest_point_on_triangle.h"
#include "core/common/parallel_for.h"
#include "core/mesh/mesh.h"

namespace sagrid {

namespace {

// One Embree device per process: creating a device spins up its thread pool, which is far more
// expensive than building a scene.
RTCDevice sharedDevice() {
  static RTCDevice device = [] {
    RTCDevice created = rtcNewDevice(nullptr);
    if (!created) throw Error("Embree: cannot create a device (error " +
                              std::to_string(rtcGetDeviceError(nullptr)) + ")");
    return created;
  }();
  return device;
}

// Below this many queries the thread start-up costs more than it saves.
constexpr std::size_t kParallelThreshold = 512;

}  // namespace

struct SurfaceScene::Impl {
  RTCScene scene = nullptr;
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3i> triangles;
  float initialQueryRadius = std::numeric_limits<float>::infinity();

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
  }

  Eigen::Vector3f unitNormal(int tri) const {
    const Eigen::Vector3i& t = triangles[tri];
    const Eigen::Vector3f n =
        (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]);
    const float length = n.norm();
    return length > 0 ? Eigen::Vector3f(n / length) : Eigen::Vector3f::UnitZ();
  }
};

namespace {

struct PointQueryState {
  const std::vector<Eigen::Vector3f>* positions;
  const std::vector<Eigen::Vector3i>* triangles;
  ClosestPoint best;
};

bool closestPointCallback(RTCPointQueryFunctionArguments* args) {
  auto* state = static_cast<PointQueryState*>(args->userPtr);
  const auto& positions = *state->positions;
  const Eigen::Vector3i& t = (*state->triangles)[args->primID];
  const Eigen::Vector3f q(args->query->x, args->query->y, args->query->z);
  const Eigen::Vector3f p = closestPointOnTriangle(q, positions[t[0]], positions[t[1]], positions[t[2]]);
  const float d = (p - q).norm();
  // Embree may report triangles outside the query sphere (its culling is conservative); taking
  // one would grow the radius, which Embree forbids, and could hide a closer triangle.
  if (d <= args->query->radius && d < state->best.distance) {
    state->best.distance = d;
    state->best.position = p;
    state->best.triangle = static_cast<int>(args->primID);
    args->query->radius = d;  // shrink the search: only closer triangles matter now
    return true;
  }
  return false;
}

}  // namespace

SurfaceScene::SurfaceScene(const Mesh& mesh) : m_impl(std::make_unique<Impl>()) {
  m_impl->positions = mesh.positions;
  m_impl->triangles = mesh.triangles;
  if (!mesh.triangles.empty()) {
    const float diagonal = mesh.bounds().diagonal().norm();
    if (diagonal > 0 && std::isfinite(diagonal)) m_impl->initialQueryRadius = diagonal / 64.0f;
  }
  RTCDevice device = sharedDevice();
  m_impl->scene = rtcNewScene(device);
  // Medium quality: no spatial splits (Debian's Embree 3.13 asserted once in the spatial-split
  // builder, heuristic_spatial_array.h:423, when scenes were built in a loop) and a faster build.
  rtcSetSceneBuildQuality(m_impl->scene, RTC_BUILD_QUALITY_MEDIUM);
  if (!mesh.triangles.empty()) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree reads vertices with 16-byte loads, so the buffer it allocates is padded for that.
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
        mesh.positions.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
        mesh.triangles.size()));
    if (!vertices || !indices) {
      rtcReleaseGeometry(geometry);
      throw Error("Embree: out of memory building the scene");
    }
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      for (int k = 0; k < 3; ++k) vertices[3 * i + k] = mesh.positions[i][k];
    }
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      for (int k = 0; k < 3; ++k) indices[3 * i + k] = static_cast<unsigned>(mesh.triangles[i][k]);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(m_impl->scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(m_impl->scene);
  if (const RTCError error = rtcGetDeviceError(device); error != RTC_ERROR_NONE) {
    throw Error("Embree: building the scene failed (error " + std::to_string(error) + ")");
  }
}

SurfaceScene::~SurfaceScene() = default;
SurfaceScene::SurfaceScene(SurfaceScene&&) noexcept = default;
SurfaceScene& SurfaceScene::operator=(SurfaceScene&&) noexcept = default;

std::optional<SurfaceHit> SurfaceScene::intersect(const Eigen::Vector3f& origin,
                                                  const Eigen::Vector3f& direction, float tNear,
                                                  float tFar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit{};
  rayHit.ray.org_x = origin.x();
  rayHit.ray.org_y = origin.y();
  rayHit.ray.org_z = origin.z();
  rayHit.ray.dir_x = direction.x();
  rayHit.ray.dir_y = direction.y();
  rayHit.ray.dir_z = direction.z();
  rayHit.ray.tnear = tNear;
  rayHit.ray.tfar = tFar;
  rayHit.ray.mask = 0xFFFFFFFFu;
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(m_impl->scene, &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  SurfaceHit hit;
  hit.distance = rayHit.ray.tfar;
  hit.triangle = static_cast<int>(rayHit.hit.primID);
  hit.u = rayHit.hit.u;
  hit.v = rayHit.hit.v;
  const Eigen::Vector3i& t = m_impl->triangles[hit.triangle];
  const auto& p = m_impl->positions;
  // Interpolating the vertices is more accurate than origin + t * direction far from the origin.
  hit.position = (1 - hit.u - hit.v) * p[t[0]] + hit.u * p[t[1]] + hit.v * p[t[2]];
  hit.normal = m_impl->unitNormal(hit.triangle);
  if (hit.normal.dot(direction) > 0) hit.normal = -hit.normal;
  return hit;
}

bool SurfaceScene::occluded(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction,
                            float tNear, float tFar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = origin.x();
  ray.org_y = origin.y();
  ray.org_z = origin.z();
  ray.dir_x = direction.x();
  ray.dir_y = direction.y();
  ray.dir_z = direction.z();
  ray.tnear = tNear;
  ray.tfar = tFar;
  ray.mask = 0xFFFFFFFFu;
  rtcOccluded1(m_impl->scene, &context, &ray);
  return ray.tfar < 0;  // Embree sets tfar to -inf on a hit
}

void SurfaceScene::intersectMany(const std::vector<Eigen::Vector3f>& origins,
                                 const std::vector<Eigen::Vector3f>& directions,
                                 std::vector<std::optional<SurfaceHit>>& hits) const {
  if (origins.size() != directions.size()) {
    throw InvalidArgument("intersectMany: " + std::to_string(origins.size()) + " origins but " +
                          std::to_string(directions.size()) + " directions");
  }
  hits.assign(origins.size(), std::nullopt);
  // Single rays on several threads: for incoherent rays (views, picking) Embree's packet paths
  // bring little, and threads scale with the cores.
  parallelFor(origins.size(), kParallelThreshold, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) hits[i] = intersect(origins[i], directions[i]);
  });
}

ClosestPoint SurfaceScene::closestPoint(const Eigen::Vector3f& query) const {
  PointQueryState state{&m_impl->positions, &m_impl->triangles, {}};
  state.best.distance = std::numeric_limits<float>::infinity();
  state.best.position = query;
  state.best.normal = Eigen::Vector3f::UnitZ();
  if (m_impl->triangles.empty() || !query.allFinite()) return state.best;
  // Embree culls BVH nodes by the query sphere but does not visit them nearest-first, so a query
  // that starts with an infinite radius touches much of the tree before it shrinks. Starting
  // small and growing 4x until something is found visits only nearby nodes; the first radius
  // that finds a triangle gives the exact closest point (everything within it was examined).
  float radius = m_impl->initialQueryRadius;
  for (;;) {
    RTCPointQuery pointQuery;
    pointQuery.x = query.x();
    pointQuery.y = query.y();
    pointQuery.z = query.z();
    pointQuery.time = 0;
    pointQuery.radius = radius;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(m_impl->scene, &pointQuery, &context, closestPointCallback, &state);
    if (state.best.triangle >= 0 || std::isinf(radius)) break;
    radius = radius < 1e30f ? radius * 4.0f : std::numeric_limits<float>::infinity();
  }
  if (state.best.triangle >= 0) state.best.normal = m_impl->unitNormal(state.best.triangle);
  return state.best;
}

std::vector<ClosestPoint> SurfaceScene::closestPoints(const std::vector<Eigen::Vector3f>& queries) const {
  std::vector<ClosestPoint> results(queries.size());
  parallelFor(queries.size(), kParallelThreshold, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) results[i] = closestPoint(queries[i]);
  });
  return results;
}

}  // namespace sagrid
