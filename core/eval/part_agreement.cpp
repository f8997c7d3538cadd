#include "core/eval/part_agreement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/sha256.h"
#include "core/controls/control_part.h"
#include "core/controls/control_record.h"
#include "core/controls/control_symmetry.h"
#include "core/dataset/object_source.h"
#include "core/eval/part_truth.h"
#include "core/labels/labels.h"
#include "core/mesh/mesh_import.h"

namespace sagrid {

namespace {

// Both sorted.
double areaIou(const std::vector<int>& a, const std::vector<int>& b, const std::vector<float>& area) {
  const auto areaOf = [&](int t) {
    return t >= 0 && static_cast<std::size_t>(t) < area.size() ? double(area[std::size_t(t)]) : 0.0;
  };
  std::vector<int> both, either;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(either));
  double inter = 0, uni = 0;
  for (int t : both) inter += areaOf(t);
  for (int t : either) uni += areaOf(t);
  if (a.empty() && b.empty()) return 1.0;  // two discs: no triangle either way
  return uni > 0 ? inter / uni : 0.0;
}

double lineAngleDegrees(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  const double c = std::min(1.0, std::abs(static_cast<double>(a.normalized().dot(b.normalized()))));
  return std::acos(c) * 180.0 / M_PI;
}

}  // namespace

PartAgreementReport measurePartAgreement(const std::vector<DatasetEntry>& entries,
                                         const PartTruth* truth) {
  PartAgreementReport report;
  std::set<std::string> unmatched;  // objects of the truth not among the entries
  if (truth)
    for (const auto& [id, object] : truth->objects) unmatched.insert(id);
  for (const DatasetEntry& entry : entries) {
    if (truth && !truth->objects.count(entry.id)) continue;
    unmatched.erase(entry.id);
    try {
      ObjectLabels labels = readLabels(entry.labels);
      const UpAxis up = upAxisOrZ(labels.object.up);
      std::filesystem::path recordsFile = entry.labels;
      if (truth) {
        const auto marked = truth->objects.find(entry.id);
        const std::string sha = sha256Hex(readFileBytes(entry.mesh));
        if (sha != marked->second.meshSha256)
          throw FileError(entry.mesh, "changed since its parts were marked (sha256 " + sha.substr(0, 12) +
                                          ", marked on " + marked->second.meshSha256.substr(0, 12) + ")");
        for (auto& point : labels.affordances) point.extra.erase(kControlField);
        for (const auto& [point, control] : marked->second.controls) {
          const auto index = static_cast<std::size_t>(point - 1);
          if (index >= labels.affordances.size() || labels.affordances[index].type != "togglebutton")
            throw FileError(truth->file, "point " + std::to_string(point) + " is no toggle button of " +
                                             entry.labels.string());
          labels.affordances[index].extra[kControlField] = control;
        }
        recordsFile = truth->file;
      }
      std::vector<std::size_t> toggles;
      std::vector<std::optional<ControlRecord>> records;
      bool anyConfirmed = false;
      for (std::size_t i = 0; i < labels.affordances.size(); ++i) {
        if (labels.affordances[i].type != "togglebutton") continue;
        toggles.push_back(i);
        records.push_back(readControlRecord(labels.affordances[i], up, recordsFile));
        anyConfirmed = anyConfirmed || (records.back() && records.back()->confirmed);
      }
      if (!anyConfirmed) continue;
      const Mesh mesh = importMesh(entry.mesh, ImportOptions(up));
      std::vector<Eigen::Vector3f> points;
      for (std::size_t i : toggles) points.push_back(fileToZUp(labels.affordances[i].position, up));
      const ControlParts found = findControlParts(mesh, points);
      const std::vector<float> area = triangleAreas(mesh);
      ++report.objects;
      const std::string source =
          objectSource(labels, entry.mesh, entry.mesh.parent_path().parent_path().filename().string());
      for (std::size_t k = 0; k < toggles.size(); ++k) {
        if (!records[k] || !records[k]->confirmed) continue;
        const ControlPart& marked = records[k]->part;
        PartAgreement a;
        a.object = labels.object.id.empty() ? entry.id : labels.object.id;
        a.source = source;
        a.point = static_cast<int>(toggles[k]) + 1;
        a.motion = toString(marked.motion);
        if (marked.motion == ControlMotion::Knob) {
          if (const auto own = revolutionAxis(mesh, marked.triangles)) {
            a.markOffOwnAxisDegrees = lineAngleDegrees(own->axis, marked.axis);
            a.ownAxisMisfit = own->misfit;
          }
        }
        if (found.parts[k]) {
          a.found = toString(found.parts[k]->origin);
          a.iou = areaIou(found.parts[k]->triangles, marked.triangles, area);
          a.axisDegrees = lineAngleDegrees(found.parts[k]->axis, marked.axis);
        } else {
          a.found = "site";
        }
        report.points.push_back(a);
      }
    } catch (const Error& e) {
      report.skipped.push_back(entry.id + ": " + e.what());
    }
  }
  for (const std::string& id : unmatched)
    report.skipped.push_back(id + ": marked in " + truth->file.string() + ", not among the data");
  const double n = static_cast<double>(std::max<std::size_t>(report.points.size(), 1));
  for (const PartAgreement& a : report.points) {
    report.meanIou += a.iou / n;
    report.meanAxisDegrees += a.axisDegrees / n;
    report.shareIouAtLeast08 += (a.iou >= 0.8 ? 1.0 : 0.0) / n;
    report.shareAxisWithin10 += (a.axisDegrees <= 10.0 ? 1.0 : 0.0) / n;
  }
  return report;
}

std::string partAgreementMarkdown(const PartAgreementReport& r) {
  std::ostringstream md;
  md.setf(std::ios::fixed);
  md.precision(2);
  md << "# Found control parts against the curator's\n\n"
     << r.points.size() << " parts the curator confirmed or marked, on " << r.objects << " objects: mean triangle IoU (by area) "
     << r.meanIou << ", " << 100 * r.shareIouAtLeast08 << " % at 0.8 or more; mean axis angle "
     << r.meanAxisDegrees << " deg, " << 100 * r.shareAxisWithin10 << " % within 10 deg.\n\n";
  // Per source: parts, mean IoU, axis within 10 degrees.
  std::map<std::string, std::array<double, 3>> bySource;
  for (const PartAgreement& a : r.points) {
    auto& row = bySource[a.source];
    row[0] += 1, row[1] += a.iou, row[2] += a.axisDegrees <= 10.0 ? 1 : 0;
  }
  md << "| source | parts | mean IoU | axis within 10 deg |\n|---|---:|---:|---:|\n";
  for (const auto& [source, row] : bySource)
    md << "| " << source << " | " << static_cast<int>(row[0]) << " | " << row[1] / row[0] << " | "
       << 100 * row[2] / row[0] << " % |\n";
  md << "\n| object | source | point | curator's motion | found as | IoU | axis (deg) | mark vs "
        "the knob's own axis (deg) | own-axis misfit |\n"
     << "|---|---|---:|---|---|---:|---:|---:|---:|\n";
  const auto optional = [](const std::optional<double>& v, int digits) {
    if (!v) return std::string("-");
    std::ostringstream o;
    o.setf(std::ios::fixed);
    o.precision(digits);
    o << *v;
    return o.str();
  };
  for (const PartAgreement& a : r.points)
    md << "| " << a.object << " | " << a.source << " | " << a.point << " | " << a.motion << " | "
       << a.found << " | " << a.iou << " | " << a.axisDegrees << " | "
       << optional(a.markOffOwnAxisDegrees, 2) << " | " << optional(a.ownAxisMisfit, 3) << " |\n";
  for (const std::string& s : r.skipped) md << "\nSkipped: " << s << "\n";
  return md.str();
}

nlohmann::json toJson(const PartAgreementReport& r) {
  nlohmann::json points = nlohmann::json::array();
  for (const PartAgreement& a : r.points) {
    nlohmann::json p = {{"object", a.object}, {"point", a.point}, {"motion", a.motion},
                        {"source", a.source}, {"found", a.found}, {"iou", a.iou},
                        {"axis_degrees", a.axisDegrees}};
    if (a.markOffOwnAxisDegrees) p["mark_off_own_axis_degrees"] = *a.markOffOwnAxisDegrees;
    if (a.ownAxisMisfit) p["own_axis_misfit"] = *a.ownAxisMisfit;
    points.push_back(p);
  }
  return {{"objects", r.objects},
          {"confirmed_parts", r.points.size()},
          {"mean_iou", r.meanIou},
          {"share_iou_at_least_0_8", r.shareIouAtLeast08},
          {"mean_axis_degrees", r.meanAxisDegrees},
          {"share_axis_within_10_degrees", r.shareAxisWithin10},
          {"points", points},
          {"skipped", r.skipped}};
}

}  // namespace sagrid
