#include "core/export/control_geometry.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/common/error.h"
#include "core/controls/control_record.h"
#include "core/export/export_frame.h"
#include "core/export/visual_parts.h"
#include "core/mesh/mesh_import.h"
#include "core/mesh/triangle_subset.h"

namespace sagrid::exportdetail {

namespace {

constexpr double kMinControlMass = 0.001;     // kg
constexpr double kMinControlInertia = 1e-8;   // kg m^2
constexpr int kControlMassResolution = 32;    // voxels along a part's largest extent

std::string pointName(std::size_t index, const AffordancePoint& point) {
  return "toggle button point " + std::to_string(index + 1) + " (" + point.type + ")";
}

// A thin solid disc about `axis` through the origin.
physics::MassProperties discMass(float radius) {
  physics::MassProperties mass;
  mass.density = kControlDensity;
  mass.volume = M_PI * radius * radius * kDiscThickness;
  mass.mass = std::max(kMinControlMass, mass.density * mass.volume);
  const double across = mass.mass * (3.0 * radius * radius + kDiscThickness * kDiscThickness) / 12.0;
  const double about = 0.5 * mass.mass * radius * radius;
  mass.principalMoments = Eigen::Vector3d(across, across, about).cwiseMax(kMinControlInertia);
  mass.inertia = mass.principalMoments.asDiagonal();
  return mass;
}

physics::MassProperties partMass(const Mesh& partMesh, const ControlPart& part) {
  physics::MassOptions options;
  options.density = kControlDensity;
  options.resolution = kControlMassResolution;
  physics::MassProperties mass;
  try {
    mass = physics::estimateMassProperties(partMesh, options);
  } catch (const Error&) {
    return discMass(std::max(part.radius, 0.005f));
  }
  if (mass.mass < kMinControlMass) mass = physics::withMass(mass, kMinControlMass);
  mass.principalMoments = mass.principalMoments.cwiseMax(kMinControlInertia);
  mass.inertia = mass.principalAxes.toRotationMatrix() * mass.principalMoments.asDiagonal() *
                 mass.principalAxes.toRotationMatrix().transpose();
  if (part.motion == ControlMotion::Knob) {
    // A knob is round about its axis: its centre of mass lies on it (the pivot is on the axis).
    const Eigen::Vector3d axis = part.axis.cast<double>();
    mass.centerOfMass = axis * axis.dot(mass.centerOfMass);
  }
  return mass;
}

}  // namespace

ControlMotionRange controlMotionRange(const ControlPart& part, bool tapHandle) {
  if (!isHinge(part.motion) && !tapHandle) return {false, part.axis, 0.0, kButtonTravel};
  const Eigen::Vector3f axis = isHinge(part.motion) ? part.axis : Eigen::Vector3f(-part.axis);
  return {true, axis, 0.0, tapHandle ? kHandleRange : kKnobRange};
}

ControlSplit splitControls(const ObjectLabels& labels, const Mesh& mesh, double metersPerUnit,
                           const std::filesystem::path& labelsPath,
                           std::vector<std::string>& warnings) {
  ControlSplit split;
  split.body.assign(mesh.triangles.size(), true);
  const UpAxis up = upAxisOrZ(labels.object.up);
  std::vector<std::size_t> toggles;
  std::vector<Eigen::Vector3f> positions;
  std::vector<std::optional<ControlRecord>> records;
  for (std::size_t i = 0; i < labels.affordances.size(); ++i) {
    const AffordancePoint& point = labels.affordances[i];
    if (point.type != "togglebutton") continue;
    toggles.push_back(i);
    positions.push_back(toSimulatorFrame(labels, point.position, metersPerUnit));
    records.push_back(readControlRecord(point, up, labelsPath));
  }
  if (toggles.empty()) return split;
  const bool allRecorded =
      std::all_of(records.begin(), records.end(), [](const auto& r) { return r.has_value(); });
  ControlParts found;
  if (!allRecorded) found = findControlParts(mesh, positions);
  const float scale = static_cast<float>(metersPerUnit);

  const std::vector<float> areas = triangleAreas(mesh);
  const float totalArea = std::accumulate(areas.begin(), areas.end(), 0.0f);

  for (std::size_t k = 0; k < toggles.size(); ++k) {
    const std::size_t index = toggles[k];
    const std::string name = pointName(index, labels.affordances[index]);
    std::optional<ControlPart> part;
    std::optional<int> drives;
    if (records[k]) {
      part = records[k]->part;
      part->pivot *= scale;
      part->radius *= scale;
      drives = records[k]->drives;
      for (int t : part->triangles)
        if (static_cast<std::size_t>(t) >= mesh.triangles.size())
          throw FileError(labelsPath, "affordance control.part.triangles: " + name +
                                          " names triangle " + std::to_string(t) +
                                          "; the mesh has " +
                                          std::to_string(mesh.triangles.size()));
    } else {
      part = found.parts[k];
      if (!found.warnings[k].empty()) warnings.push_back(name + ": " + found.warnings[k]);
      if (!part) continue;
    }
    // Triangles another control took stay with it.
    std::vector<int> own;
    float area = 0;
    for (int t : part->triangles)
      if (split.body[static_cast<std::size_t>(t)]) own.push_back(t), area += areas[static_cast<std::size_t>(t)];
    if (own.size() < part->triangles.size())
      warnings.push_back(name + ": " + std::to_string(part->triangles.size() - own.size()) +
                         " of its triangles belong to another control");
    if (area > kMaxControlAreaShare * totalArea) {
      warnings.push_back(name + ": its part would take most of the object; site only");
      continue;
    }
    part->triangles = std::move(own);
    ControlGeometry control;
    control.point = index;
    control.drives = drives;
    if (!part->triangles.empty()) {
      std::vector<bool> keep(mesh.triangles.size(), false);
      for (int t : part->triangles) keep[static_cast<std::size_t>(t)] = true;
      control.mesh = triangleSubset(mesh, keep);
      for (auto& p : control.mesh.positions) p -= part->pivot;
      if (!spansVolume(control.mesh)) {
        // Flat: it stays drawn on the body and a thin disc moves in its place.
        warnings.push_back(name + ": its part is flat; a thin disc slides in its place");
        control.mesh = Mesh();
        if (part->motion != ControlMotion::Button) part->axis = pressDirection(mesh, part->triangles);
        part->triangles.clear();
        part->motion = ControlMotion::Button;
        part->origin = PartOrigin::Disc;
      } else {
        for (int t : part->triangles) split.body[static_cast<std::size_t>(t)] = false;
      }
    }
    if (part->origin == PartOrigin::Disc && part->radius <= 0) part->radius = 0.01f;
    control.mass = control.mesh.triangles.empty() ? discMass(part->radius) : partMass(control.mesh, *part);
    control.axisLow = control.axisHigh = 0;
    for (const auto& p : control.mesh.positions) {
      const float h = p.dot(part->axis);
      control.axisLow = std::min(control.axisLow, h), control.axisHigh = std::max(control.axisHigh, h);
    }
    if (control.mesh.positions.empty()) {
      control.axisLow = -0.5f * static_cast<float>(kDiscThickness);
      control.axisHigh = 0.5f * static_cast<float>(kDiscThickness);
    }
    control.part = std::move(*part);
    split.controls.push_back(std::move(control));
  }
  return split;
}

}  // namespace sagrid::exportdetail
