#include "core/generate/contact_sheet.h"

#include <algorithm>
#include <cmath>

#include "core/common/atomic_file.h"
#include "core/dataset/dataset.h"
#include "core/geometry/surface_scene.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_import.h"
#include "core/render/multiview_renderer.h"
#include "core/render/view_camera.h"

namespace sagrid::gen {

namespace {

constexpr float kDegrees = 3.14159265358979f / 180.0f;

Eigen::Vector3f colorOf(const std::string& type) {
  if (type == "heatsource") return {1.0f, 0.1f, 0.05f};
  if (type == "fluidsource") return {0.1f, 0.35f, 1.0f};
  if (type == "togglebutton") return {0.1f, 0.95f, 0.2f};
  return {0.7f, 0.7f, 0.7f};
}

void putPixel(Texture& sheet, int x, int y, const Eigen::Vector3f& c) {
  if (x < 0 || y < 0 || x >= sheet.width || y >= sheet.height) return;
  std::uint8_t* p = &sheet.rgba[(static_cast<std::size_t>(y) * sheet.width + x) * 4];
  for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
  p[3] = 255;
}

void drawDot(Texture& sheet, float cx, float cy, float radius, const Eigen::Vector3f& color) {
  const int r = static_cast<int>(std::ceil(radius + 1));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const float d = std::sqrt(float(dx * dx + dy * dy));
      const int x = static_cast<int>(std::floor(cx)) + dx, y = static_cast<int>(std::floor(cy)) + dy;
      if (d <= radius - 0.8f) putPixel(sheet, x, y, color);
      else if (d <= radius + 0.6f) putPixel(sheet, x, y, Eigen::Vector3f::Zero());  // outline
    }
  }
}

}  // namespace

Texture renderContactSheet(const std::vector<SheetItem>& items, const ContactSheetOptions& options) {
  const int views = std::max(1, options.viewsPerItem);
  const int cells = static_cast<int>(items.size()) * views;
  int columns = options.columns > 0 ? options.columns
                                    : std::max(1, static_cast<int>(std::ceil(std::sqrt(double(std::max(1, cells))))));
  if (views > 1) columns = std::max(columns / views, 1) * views;
  const int rows = std::max(1, (cells + columns - 1) / columns);
  const int size = options.thumbnail;
  Texture sheet;
  sheet.width = columns * size;
  sheet.height = rows * size;
  sheet.rgba.assign(static_cast<std::size_t>(sheet.width) * sheet.height * 4, 255);
  for (std::size_t i = 0; i < sheet.rgba.size(); i += 4) sheet.rgba[i] = sheet.rgba[i + 1] = sheet.rgba[i + 2] = 235;

  for (std::size_t item = 0; item < items.size(); ++item) {
    const Mesh& source = *items[item].mesh;
    if (source.triangles.empty()) continue;
    // Normalize into the unit cube around the origin, as the feature pipeline does.
    const Eigen::AlignedBox3f box = source.bounds();
    const Eigen::Vector3f center = box.center();
    const float scale = 1.0f / std::max(1e-12f, box.sizes().maxCoeff());
    Mesh mesh = source;
    for (auto& p : mesh.positions) p = (p - center) * scale;
    const SurfaceScene scene(mesh);
    const MultiViewRenderer renderer(mesh, scene);
    for (int v = 0; v < views; ++v) {
      const int cell = static_cast<int>(item) * views + v;
      const int ox = (cell % columns) * size, oy = (cell / columns) * size;
      const ViewCamera camera = ViewCamera::lookAtOrigin((options.yawDegrees + 360.0f * v / views) * kDegrees,
                                                         options.pitchDegrees * kDegrees, 2.0f, 36.0f * kDegrees);
      const RenderedView view = renderer.render(camera, size);
      for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
          const std::size_t p = static_cast<std::size_t>(y) * size + x;
          if (!view.mask[p]) continue;
          putPixel(sheet, ox + x, oy + y, Eigen::Vector3f(view.rgb[p * 3], view.rgb[p * 3 + 1], view.rgb[p * 3 + 2]));
        }
      }
      for (const auto& point : items[item].points) {
        float depth = 0;
        const Eigen::Vector2f uv = camera.project((point.position - center) * scale, &depth);
        if (depth <= 0) continue;
        drawDot(sheet, ox + uv.x() * size, oy + uv.y() * size, std::max(2.0f, size / 45.0f), colorOf(point.type));
      }
    }
  }
  return sheet;
}

void writeContactSheet(const std::filesystem::path& path, const std::vector<SheetItem>& items,
                       const ContactSheetOptions& options) {
  writeFileAtomic(path, encodePng(renderContactSheet(items, options)));
}

void writeDatasetContactSheet(const std::filesystem::path& datasetDir, const std::filesystem::path& pngPath, int limit,
                              const ContactSheetOptions& options) {
  const auto entries = readDataset(datasetDir);
  std::vector<Mesh> meshes;
  std::vector<std::vector<SheetPoint>> points;
  for (const auto& entry : entries) {
    if (static_cast<int>(meshes.size()) >= limit) break;
    // The labels record the file's up axis (a y-up OBJ would otherwise lie on its side).
    const ObjectLabels labels = readLabels(entry.labels);
    Mesh mesh = importMesh(entry.mesh, ImportOptions(upAxisOrZ(labels.object.up)));
    std::vector<SheetPoint> pts;
    for (const auto& a : labels.affordances) pts.push_back({a.type, fileToZUp(a.position, mesh.fileUp)});
    meshes.push_back(std::move(mesh));
    points.push_back(std::move(pts));
  }
  std::vector<SheetItem> items;
  for (std::size_t i = 0; i < meshes.size(); ++i) items.push_back({&meshes[i], points[i]});
  writeContactSheet(pngPath, items, options);
}

}  // namespace sagrid::gen
