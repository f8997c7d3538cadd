#include "core/export/mjcf_controls.h"

#include <algorithm>
#include <cmath>

#include "core/common/atomic_file.h"
#include "core/export/export_frame.h"
#include "core/export/stl_file.h"
#include "core/export/xml_text.h"

namespace sagrid::exportdetail {

namespace fs = std::filesystem;

namespace {

constexpr double kMinGeomSize = 0.001;  // metres; MuJoCo refuses zero-sized geoms
constexpr double kCollisionShrink = 0.9;  // a control's collision stays inside its visual
// A body that carries a joint and a site but nothing to weigh (a spout's outlet, a button's
// switch): the least mass and inertia MuJoCo accepts without complaint.
constexpr double kMarkerMass = 0.001;
constexpr double kMarkerInertia = 1e-8;

std::string rgbaFor(const std::string& type) {
  if (type == "heatsource") return "1 0.4 0.1 0.6";
  if (type == "fluidsource") return "0.2 0.6 1 0.6";
  if (type == "togglebutton") return "0.3 0.9 0.35 0.6";
  return "0.9 0.9 0.2 0.6";
}

Eigen::Vector3f meshColor(const Mesh& mesh) {
  if (!mesh.triangleMaterials.empty()) {
    const int m = mesh.triangleMaterials.front();
    if (m >= 0 && static_cast<std::size_t>(m) < mesh.materials.size()) return mesh.materials[m].baseColor;
  }
  return Eigen::Vector3f(0.8f, 0.8f, 0.8f);
}

std::string quat(const Eigen::Quaterniond& q) {
  return formatNumber(q.w()) + " " + formatNumber(q.x()) + " " + formatNumber(q.y()) + " " +
         formatNumber(q.z());
}

// A collision geom the turn does not change: a cylinder about a knob's or button's axis, a capsule
// from a lever's pivot to its farthest point.
void writeCollisionGeom(std::ostringstream& xml, const ControlGeometry& control,
                        const std::string& body) {
  const ControlPart& part = control.part;
  const Eigen::Vector3d axis = part.axis.cast<double>();
  Eigen::Vector3d from, to;
  double radius = std::max(kMinGeomSize, kCollisionShrink * part.radius);
  if (part.motion == ControlMotion::Lever && !control.mesh.positions.empty()) {
    Eigen::Vector3f tip = Eigen::Vector3f::Zero();
    for (const auto& p : control.mesh.positions)
      if (p.norm() > tip.norm()) tip = p;
    from = Eigen::Vector3d::Zero(), to = tip.cast<double>();
    // A lever is thin: its width is the spread across its length.
    double width = 0;
    const Eigen::Vector3d along = to.normalized();
    for (const auto& p : control.mesh.positions) {
      const Eigen::Vector3d q = p.cast<double>();
      width = std::max(width, (q - along * along.dot(q)).norm());
    }
    radius = std::max(kMinGeomSize, 0.5 * kCollisionShrink * width);
  } else {
    from = axis * control.axisLow, to = axis * control.axisHigh;
    if ((to - from).norm() < 2 * kMinGeomSize) to = from + axis * 2 * kMinGeomSize;
  }
  xml << "        <geom name=\"" << escapeXml(body) << "_collision\" type=\""
      << (part.motion == ControlMotion::Lever ? "capsule" : "cylinder") << "\" fromto=\""
      << formatVector(from) << " " << formatVector(to) << "\" size=\"" << formatNumber(radius)
      << "\" group=\"0\" rgba=\"0.5 0.5 0.5 1\"/>\n";
}

void writeMarkerInertial(std::ostringstream& xml) {
  xml << "        <inertial pos=\"0 0 0\" mass=\"" << formatNumber(kMarkerMass)
      << "\" diaginertia=\"" << formatNumber(kMarkerInertia) << " " << formatNumber(kMarkerInertia)
      << " " << formatNumber(kMarkerInertia) << "\"/>\n";
}

void writeJoint(std::ostringstream& xml, const MjcfJoint& joint) {
  xml << "        <joint name=\"" << escapeXml(joint.name) << "\" type=\"" << joint.type
      << "\" pos=\"0 0 0\" axis=\"" << formatVector(joint.axis.cast<double>())
      << "\" limited=\"true\" range=\"" << formatNumber(joint.low) << " "
      << formatNumber(joint.high) << "\" damping=\"" << formatNumber(joint.damping)
      << "\" armature=\"" << formatNumber(joint.armature) << "\"";
  if (joint.frictionLoss > 0) xml << " frictionloss=\"" << formatNumber(joint.frictionLoss) << "\"";
  if (joint.stiffness > 0)
    xml << " stiffness=\"" << formatNumber(joint.stiffness) << "\" springref=\""
        << formatNumber(joint.springRef) << "\"";
  xml << "/>\n";
}

}  // namespace

bool pressDrivesSwitch(const ControlGeometry& control, const std::string& body,
                       const std::set<std::string>& burnerSites) {
  const std::string knob = "knob_";
  return !controlMotionRange(control.part, false).hinge && body.rfind(knob, 0) == 0 &&
         burnerSites.count("burner_on_" + body.substr(knob.size())) > 0;
}

std::vector<MjcfJoint> controlJoints(const ControlGeometry& control, const std::string& body,
                                     bool onlySinkHandle, bool drivesSwitch) {
  std::vector<MjcfJoint> joints;
  const ControlMotionRange motion =
      controlMotionRange(control.part, body.rfind("handle", 0) == 0);
  MjcfJoint joint{body + (drivesSwitch ? "_press_joint" : "_joint"),
                  motion.hinge ? "hinge" : "slide", motion.axis, motion.low, motion.high};
  if (!motion.hinge) {
    joint.frictionLoss = kButtonHold;
    // Its weight along the press (z is up): carried by a long spring from the other side.
    const double weight = control.mass.mass * kGravity * -static_cast<double>(motion.axis.z());
    joint.stiffness = std::abs(weight) / kCarrySpringLength;
    joint.springRef = weight > 0 ? -kCarrySpringLength : kCarrySpringLength;
  }
  joints.push_back(joint);
  if (!motion.hinge) return joints;
  if (onlySinkHandle)
    joints.push_back({"handle_temp_joint", "hinge", Eigen::Vector3f::UnitZ(), -kTemperatureRange,
                      kTemperatureRange});
  return joints;
}

void writeControlAssets(std::ostringstream& xml, const std::vector<ControlGeometry>& controls,
                        const std::vector<std::string>& bodies, const fs::path& folder) {
  for (std::size_t i = 0; i < controls.size(); ++i) {
    if (controls[i].mesh.triangles.empty()) continue;
    const std::string name = "visual_" + bodies[i];
    writeFileAtomic(folder / "meshes" / (name + ".stl"), encodeBinaryStl(controls[i].mesh));
    const Eigen::Vector3f color = meshColor(controls[i].mesh);  // the cut part keeps materials
    xml << "    <material name=\"" << escapeXml(name) << "\" rgba=\""
        << formatVector(color.cast<double>()) << " 1\"/>\n"
        << "    <mesh name=\"" << escapeXml(name) << "\" file=\"meshes/" << escapeXml(name)
        << ".stl\"/>\n";
  }
}

void writeContactExclusions(std::ostringstream& xml, const std::vector<std::string>& bodies) {
  if (bodies.empty()) return;
  xml << "  <contact>\n";
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    xml << "    <exclude body1=\"object\" body2=\"" << escapeXml(bodies[i]) << "\"/>\n";
    // Neighbouring controls' collision shapes may overlap where their parts nearly touch (a knob
    // row): one turned must not drag the next along.
    for (std::size_t j = i + 1; j < bodies.size(); ++j)
      xml << "    <exclude body1=\"" << escapeXml(bodies[i]) << "\" body2=\"" << escapeXml(bodies[j])
          << "\"/>\n";
  }
  xml << "  </contact>\n";
}

void writeSite(std::ostringstream& xml, const MjcfSite& site, const std::string& indent,
               const Eigen::Vector3f& origin) {
  xml << indent << "<site name=\"" << escapeXml(site.name) << "\" type=\"" << site.shape
      << "\" pos=\"" << formatVector((site.position - origin).cast<double>()) << "\" size=\""
      << formatNumber(site.size.x());
  if (site.shape == "cylinder") xml << " " << formatNumber(site.size.y());
  xml << "\" rgba=\"" << rgbaFor(site.affordanceType) << "\" group=\"3\"/>\n";
}

void writeControlBody(std::ostringstream& xml, const ControlGeometry& control,
                      const std::string& body, const MjcfSite& site,
                      const std::vector<MjcfJoint>& joints) {
  const ControlPart& part = control.part;
  const physics::MassProperties& mass = control.mass;
  xml << "      <body name=\"" << escapeXml(body) << "\" pos=\""
      << formatVector(part.pivot.cast<double>()) << "\">\n"
      << "        <inertial pos=\"" << formatVector(mass.centerOfMass) << "\" quat=\""
      << quat(mass.principalAxes) << "\" mass=\"" << formatNumber(mass.mass)
      << "\" diaginertia=\"" << formatVector(mass.principalMoments) << "\"/>\n";
  for (const auto& joint : joints) writeJoint(xml, joint);
  const std::string visual = "visual_" + body;
  if (!control.mesh.triangles.empty()) {
    xml << "        <geom name=\"" << escapeXml(visual) << "\" class=\"visual\" mesh=\""
        << escapeXml(visual) << "\" material=\"" << escapeXml(visual) << "\"/>\n";
  } else {  // a disc in the place of a printed key
    const Eigen::Vector3d half = part.axis.cast<double>() * 0.5 * kDiscThickness;
    xml << "        <geom name=\"" << escapeXml(visual) << "\" type=\"cylinder\" fromto=\""
        << formatVector(-half) << " " << formatVector(half) << "\" size=\""
        << formatNumber(std::max<double>(kMinGeomSize, part.radius))
        << "\" contype=\"0\" conaffinity=\"0\" group=\"1\" rgba=\"0.3 0.9 0.35 0.4\"/>\n";
  }
  writeCollisionGeom(xml, control, body);
  writeSite(xml, site, "        ", part.pivot);
  xml << "      </body>\n";
}

void writeSwitchBody(std::ostringstream& xml, const ControlGeometry& control,
                     const std::string& body) {
  xml << "      <body name=\"" << escapeXml(body) << "_switch\" pos=\""
      << formatVector(control.part.pivot.cast<double>()) << "\">\n";
  writeMarkerInertial(xml);
  MjcfJoint hinge{body + "_joint", "hinge", control.part.axis, 0.0, kSwitchAngle};
  hinge.damping = 0;
  hinge.armature = kSwitchArmature;
  writeJoint(xml, hinge);
  xml << "      </body>\n";
}

void writeSwitchEqualities(std::ostringstream& xml, const std::vector<std::string>& switchedBodies) {
  if (switchedBodies.empty()) return;
  // MuJoCo's joint equality: joint1 - its reference = polycoef(joint2 - its reference).
  xml << "  <equality>\n";
  for (const auto& body : switchedBodies)
    xml << "    <joint joint1=\"" << escapeXml(body) << "_joint\" joint2=\"" << escapeXml(body)
        << "_press_joint\" polycoef=\"0 " << formatNumber(kSwitchAngle / kButtonTravel)
        << " 0 0 0\"/>\n";
  xml << "  </equality>\n";
}

void writeSpoutBody(std::ostringstream& xml, const MjcfSite& water) {
  const std::string body = "spout" + water.name.substr(std::string("water").size());
  // The outlet: the site hangs its stream below it (robocasa_sites.cpp).
  const Eigen::Vector3f outlet = water.position + Eigen::Vector3f(0, 0, kWaterHalfHeight);
  xml << "      <body name=\"" << escapeXml(body) << "\" pos=\""
      << formatVector(outlet.cast<double>()) << "\">\n";
  writeMarkerInertial(xml);
  writeJoint(xml, {body + "_joint", "hinge", Eigen::Vector3f::UnitZ(), -kLockedRange, kLockedRange});
  writeSite(xml, water, "        ", outlet);
  xml << "      </body>\n";
}

}  // namespace sagrid::exportdetail
