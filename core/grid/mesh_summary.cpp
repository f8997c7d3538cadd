#include "core/grid/mesh_summary.h"

#include <chrono>
#include <cstdio>

#include "core/grid/voxelize.h"

namespace sagrid {

namespace {
class StageTimer {
 public:
  double lapMilliseconds() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - m_last).count();
    m_last = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point m_last = std::chrono::steady_clock::now();
};

nlohmann::json vectorJson(const Eigen::Vector3f& v) { return {v.x(), v.y(), v.z()}; }

std::string formatVector(const Eigen::Vector3f& v) {
  char text[96];
  std::snprintf(text, sizeof(text), "(%.6g, %.6g, %.6g)", v.x(), v.y(), v.z());
  return text;
}
}  // namespace

MeshSummary summarizeMesh(const std::filesystem::path& path, const ImportOptions& options,
                          int resolution) {
  MeshSummary s;
  s.path = path;
  s.resolution = resolution;
  VoxelGrid checkResolution(resolution);  // rejects a bad resolution before the slow work
  StageTimer timer;
  const Mesh mesh = importMesh(path, options);
  s.stageMilliseconds.emplace_back("import", timer.lapMilliseconds());
  s.triangles = mesh.triangleCount();
  s.vertices = mesh.vertexCount();
  s.materials = mesh.materials.size();
  s.textures = mesh.textures.size();
  s.fileUp = mesh.fileUp;
  s.fileUpDetected = mesh.fileUpDetected;
  s.fileUpConfidence = mesh.fileUpConfidence;
  s.sha256 = mesh.sha256;
  s.bounds = mesh.bounds();
  s.normalization = Normalization::fromBounds(s.bounds);
  const Mesh normalized = normalizedCopy(mesh, s.normalization);
  s.stageMilliseconds.emplace_back("normalize", timer.lapMilliseconds());
  s.occupiedVoxels = voxelize(normalized, resolution).occupiedCount();
  s.stageMilliseconds.emplace_back("voxelize", timer.lapMilliseconds());
  return s;
}

std::string formatSummary(const MeshSummary& s) {
  char line[256];
  std::string out;
  auto add = [&](const char* format, auto... args) {
    std::snprintf(line, sizeof(line), format, args...);
    out += line;
    out += '\n';
  };
  add("mesh:        %s", s.path.string().c_str());
  add("sha256:      %s", s.sha256.c_str());
  add("triangles:   %zu", s.triangles);
  add("vertices:    %zu", s.vertices);
  add("materials:   %zu (%zu textures)", s.materials, s.textures);
  if (s.fileUpDetected) {
    add("file up:     %s (detected, confidence %.2f; mesh frame is z-up)", toString(s.fileUp),
        s.fileUpConfidence);
  } else {
    add("file up:     %s (mesh frame is z-up)", toString(s.fileUp));
  }
  add("bounds min:  %s", formatVector(s.bounds.min()).c_str());
  add("bounds max:  %s", formatVector(s.bounds.max()).c_str());
  add("size:        %s", formatVector(s.bounds.sizes()).c_str());
  add("normalize:   p_norm = (p - %s) * %.9g", formatVector(s.normalization.center).c_str(),
      static_cast<double>(s.normalization.scale));
  add("occupied:    %zu of %d^3 voxels", s.occupiedVoxels, s.resolution);
  for (const auto& [stage, ms] : s.stageMilliseconds)
    add("time %-9s %.2f ms", (stage + ":").c_str(), ms);
  return out;
}

nlohmann::json summaryJson(const MeshSummary& s) {
  nlohmann::json timings = nlohmann::json::object();
  for (const auto& [stage, ms] : s.stageMilliseconds) timings[stage] = ms;
  return {{"mesh", s.path.string()},
          {"sha256", s.sha256},
          {"triangles", s.triangles},
          {"vertices", s.vertices},
          {"materials", s.materials},
          {"textures", s.textures},
          {"file_up", toString(s.fileUp)},
          {"file_up_detected", s.fileUpDetected},
          {"file_up_confidence", s.fileUpConfidence},
          {"bounds", {{"min", vectorJson(s.bounds.min())}, {"max", vectorJson(s.bounds.max())}}},
          {"normalization",
           {{"center", vectorJson(s.normalization.center)}, {"scale", s.normalization.scale}}},
          {"resolution", s.resolution},
          {"occupied_voxels", s.occupiedVoxels},
          {"time_ms", timings}};
}

}  // namespace sagrid
