#include "core/training/crop_dataset.h"

#include <algorithm>
#include <map>

#include "core/common/error.h"
#include "core/common/log.h"
#include "core/dataset/dataset.h"
#include "core/generate/dataset_generator.h"
#include "core/generate/random.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_crop.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

namespace fs = std::filesystem;

namespace {

struct Point {
  std::string type;
  Eigen::Vector3f zUp;  // z-up frame, file units
};

// The box the second pass would cut around `typePoints` after a first pass off by a random shift
// of up to the jitter; nullopt when it would not run (wider than maxCropShare of the object).
std::optional<Eigen::AlignedBox3f> cropBox(const std::vector<Eigen::Vector3f>& typePoints,
                                           const Eigen::AlignedBox3f& bounds,
                                           const CropDatasetOptions& options, gen::Rng& rng) {
  const Eigen::Vector3f shift(rng.uniformf(-1, 1), rng.uniformf(-1, 1), rng.uniformf(-1, 1));
  std::vector<Eigen::Vector3f> shifted;
  for (const auto& p : typePoints)
    shifted.push_back(p + shift * options.jitter * bounds.sizes().maxCoeff());
  return regionAround(shifted, bounds, options.margin, options.maxCropShare);
}

}  // namespace

CropDatasetSummary writeCropDataset(const fs::path& dataDir, const fs::path& outDir,
                                    const CropDatasetOptions& options,
                                    const std::function<void(int, int)>& progress) {
  const auto entries = readDataset(dataDir);
  if (entries.empty()) throw FileError(dataDir, "holds no labelled object");
  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) throw FileError(outDir, "cannot create directory: " + ec.message());

  CropDatasetSummary summary;
  std::vector<gen::ManifestLine> lines;
  int done = 0;
  for (const auto& entry : entries) {
    if (progress) progress(done++, static_cast<int>(entries.size()));
    ObjectLabels labels;
    Mesh mesh;
    try {
      labels = readLabels(entry.labels);
      mesh = importMesh(entry.mesh, ImportOptions(upAxisOrZ(labels.object.up)));
    } catch (const Error& error) {
      logger()->warn("crop dataset: skipping {}: {}", entry.id, error.what());
      continue;
    }
    ++summary.objects;
    const UpAxis up = upAxisOrZ(labels.object.up);
    std::vector<Point> points;
    std::map<std::string, std::vector<Eigen::Vector3f>> byType;
    for (const auto& a : labels.affordances) {
      points.push_back({a.type, fileToZUp(a.position, up)});
      byType[a.type].push_back(points.back().zUp);
    }
    const Eigen::AlignedBox3f bounds = mesh.bounds();
    for (const auto& [type, typePoints] : byType) {
      gen::Rng rng(gen::deriveSeed(options.seed, entry.id + "/" + type, 0));
      const auto box = cropBox(typePoints, bounds, options, rng);
      Mesh crop = box ? cropMesh(mesh, *box) : Mesh{};
      if (!box || static_cast<int>(crop.triangleCount()) < options.minTriangles) {
        ++summary.skipped;
        continue;
      }
      gen::FinishedObject out;
      out.id = entry.id + "." + type;
      out.category = labels.object.category;
      out.meshFileName = "mesh.obj";
      out.mesh = std::move(crop);
      out.mesh.fileUp = UpAxis::Z;
      ObjectLabels& cropLabels = out.labels;
      cropLabels.object.id = out.id;
      cropLabels.object.mesh = out.meshFileName;
      cropLabels.object.category = out.category;
      cropLabels.object.up = "z";
      for (const char* key : {"meters_per_unit", "units"})
        if (labels.object.extra.contains(key)) cropLabels.object.extra[key] = labels.object.extra[key];
      cropLabels.object.extra["crop_of"] = {{"id", entry.id}, {"type", type}};
      for (const auto& p : points) {
        if (!box->contains(p.zUp)) continue;
        AffordancePoint a;
        a.type = p.type;
        a.position = p.zUp;
        a.status = AffordanceStatus::Accepted;
        a.source = "crop";
        cropLabels.affordances.push_back(a);
      }
      cropLabels.reviewState = ReviewState::Done;
      lines.push_back(gen::writeDatasetObject(out, outDir));
      ++summary.crops;
    }
  }
  if (progress) progress(done, static_cast<int>(entries.size()));
  gen::writeManifest(lines, outDir);
  return summary;
}

}  // namespace sagrid
