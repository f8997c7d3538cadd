#include "core/training/curated_data_check.h"

#include <Eigen/Geometry>
#include <cstdio>
#include <map>

#include "core/common/error.h"
#include "core/dataset/dataset.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

namespace fs = std::filesystem;

namespace {

struct CuratedObject {
  fs::path labelsFile;
  bool heldOut = false;
  ObjectLabels labels;
  std::string category;
  std::vector<Eigen::Vector3f> points;  // the labels' points in the mesh's z-up frame
  Eigen::AlignedBox3f bounds;           // of the mesh, z-up frame
  float extent = 0;                     // the mesh's largest extent
  std::string sha256;
};

std::vector<CuratedObject> readObjects(const fs::path& dir, bool heldOut, const fs::path& root) {
  std::vector<CuratedObject> out;
  for (const DatasetEntry& entry : readDataset(dir, root)) {
    CuratedObject o;
    o.labelsFile = entry.labels;
    o.heldOut = heldOut;
    o.labels = readLabels(entry.labels);
    o.category = entry.category.empty() ? o.labels.object.category : entry.category;
    const UpAxis up = upAxisOrZ(o.labels.object.up);
    const Mesh mesh = importMesh(entry.mesh, ImportOptions(up));
    o.bounds = mesh.bounds();
    o.extent = o.bounds.isEmpty() ? 0.0f : o.bounds.sizes().maxCoeff();
    o.sha256 = mesh.sha256;
    for (const AffordancePoint& p : o.labels.affordances) o.points.push_back(fileToZUp(p.position, up));
    out.push_back(std::move(o));
  }
  return out;
}

std::string format(const char* pattern, double a, double b) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

// The first point lying far outside its mesh, as a problem line; empty when none does.
std::string farPoint(const CuratedObject& o) {
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    const double outside = o.bounds.exteriorDistance(o.points[i]);
    if (outside > kFarFromMeshShare * o.extent)
      return o.labelsFile.string() + ": point " + std::to_string(i) + " (" +
             o.labels.affordances[i].type + ") lies " +
             format("%.3g units outside its mesh, whose largest extent is %.3g units", outside,
                    o.extent) +
             " (labels in other units or another frame than the mesh?)";
  }
  return {};
}

// Why two labellings of one mesh disagree; empty when they agree.
std::string disagreement(const CuratedObject& a, const CuratedObject& b) {
  if (a.category != b.category) return "category " + a.category + " vs " + b.category;
  const float tolerance = float(kLabelAgreementShare) * a.extent;
  const auto unmatched = [&](const CuratedObject& from, const CuratedObject& to) -> std::string {
    for (std::size_t i = 0; i < from.points.size(); ++i) {
      const std::string& type = from.labels.affordances[i].type;
      std::size_t sameType = 0, near = 0;
      for (std::size_t j = 0; j < to.points.size(); ++j) {
        if (to.labels.affordances[j].type != type) continue;
        ++sameType;
        if ((to.points[j] - from.points[i]).norm() <= tolerance) ++near;
      }
      if (near == 0)
        return sameType == 0 ? "no " + type + " point in one of them"
                             : type + " point " + std::to_string(i) + " has no counterpart within " +
                                   format("%.3g units (%.0f %% of the mesh's extent)", tolerance,
                                          100 * kLabelAgreementShare);
    }
    return {};
  };
  if (a.points.size() != b.points.size())
    return std::to_string(a.points.size()) + " points vs " + std::to_string(b.points.size());
  std::string why = unmatched(a, b);
  return why.empty() ? unmatched(b, a) : why;
}

}  // namespace

std::vector<std::string> curatedDataProblems(const CuratedData& data) {
  std::vector<CuratedObject> objects;
  for (const fs::path& dir : data.training)
    for (auto& o : readObjects(dir, false, data.referenceRoot)) objects.push_back(std::move(o));
  if (!data.heldOut.empty())
    for (auto& o : readObjects(data.heldOut, true, data.referenceRoot)) objects.push_back(std::move(o));

  std::vector<std::string> problems;
  std::map<std::string, std::size_t> firstWithMesh;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const CuratedObject& o = objects[i];
    if (std::string far = farPoint(o); !far.empty()) problems.push_back(far);
    if (o.sha256.empty()) continue;
    const auto [it, first] = firstWithMesh.emplace(o.sha256, i);
    if (first) continue;
    const CuratedObject& earlier = objects[it->second];
    const std::string both = earlier.labelsFile.string() + " and " + o.labelsFile.string() +
                             " label the same mesh (sha256 " + o.sha256.substr(0, 12) + ")";
    if (std::string why = disagreement(earlier, o); !why.empty())
      problems.push_back(both + " differently: " + why + "; keep one");
    else if (earlier.heldOut != o.heldOut)
      problems.push_back(both + ", one held out and one trained on: the guard's figure would not "
                                "be held out; keep it on one side");
  }
  return problems;
}

void requireSoundCuratedData(const CuratedData& data) {
  const std::vector<std::string> problems = curatedDataProblems(data);
  if (problems.empty()) return;
  constexpr std::size_t kListed = 10;
  std::string text = std::to_string(problems.size()) +
                     " problem(s) in the curated data; nothing was trained and the current model "
                     "stays:";
  for (std::size_t i = 0; i < problems.size() && i < kListed; ++i) text += "\n  " + problems[i];
  if (problems.size() > kListed)
    text += "\n  ... and " + std::to_string(problems.size() - kListed) + " more";
  throw InvalidArgument(text);
}

}  // namespace sagrid
