#include "core/export/urdf_controls.h"

#include <Eigen/Geometry>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/export/export_frame.h"
#include "core/export/omnigibson_meta_links.h"
#include "core/export/urdf_xml.h"
#include "core/export/xml_text.h"
#include "core/mesh/mesh_export.h"
#include "core/physics/convex_decomposition.h"

namespace sagrid::exportdetail {

namespace fs = std::filesystem;

namespace {

constexpr double kEffort = 10.0;   // N m or N: a hand's
constexpr double kVelocity = 3.0;  // rad/s or m/s

// URDF's rpy (fixed axes x, y, z) of the rotation taking +z to `axis`: a cylinder along it.
Eigen::Vector3d rpyAlong(const Eigen::Vector3f& axis) {
  const Eigen::Matrix3d r =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis.cast<double>().normalized())
          .toRotationMatrix();
  const Eigen::Vector3d ypr = r.eulerAngles(2, 1, 0);
  return {ypr[2], ypr[1], ypr[0]};
}

std::string geometryXml(const ControlGeometry& control, const std::string& meshFile,
                        const Eigen::Vector3d& scale) {
  if (meshFile.empty()) {
    return "<cylinder radius=\"" + formatNumber(std::max(0.001f, control.part.radius)) +
           "\" length=\"" + formatNumber(kDiscThickness) + "\"/>";
  }
  return "<mesh filename=\"" + meshFile + "\" scale=\"" + formatVector(scale) + "\"/>";
}

}  // namespace

std::string controlLinksXml(const SimulatorGeometry& geometry, const std::vector<MjcfSite>& sites,
                            const std::string& model, const fs::path& root) {
  std::ostringstream xml;
  for (const auto& control : geometry.controls) {
    const std::string name = sites[control.point].name;
    const std::string link = name + "_link";
    const ControlMotionRange motion =
        controlMotionRange(control.part, name.rfind("handle", 0) == 0);
    xml << "  <joint name=\"" << escapeXml(name) << "_joint\" type=\""
        << (motion.hinge ? "revolute" : "prismatic") << "\">\n    "
        << origin(control.part.pivot.cast<double>()) << "\n    <parent link=\"" << kBaseLink
        << "\"/>\n    <child link=\"" << escapeXml(link) << "\"/>\n    <axis xyz=\""
        << formatVector(motion.axis.cast<double>()) << "\"/>\n    <limit lower=\""
        << formatNumber(motion.low) << "\" upper=\"" << formatNumber(motion.high)
        << "\" effort=\"" << formatNumber(kEffort) << "\" velocity=\"" << formatNumber(kVelocity)
        << "\"/>\n    <dynamics damping=\"" << formatNumber(kControlDamping) << "\"/>\n  </joint>\n";
    xml << "  <link name=\"" << escapeXml(link) << "\">\n";
    std::string visualFile, collisionFile;
    Eigen::Vector3d collisionScale = Eigen::Vector3d::Ones();
    Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
    if (!control.mesh.triangles.empty()) {
      Mesh visual = control.mesh;
      visual.fileUp = UpAxis::Z;
      const std::string visualName = model + "_" + link + "_visual";
      writeEncodedMeshFiles(encodeObj(visual, visualName), root / "shape" / "visual");
      visualFile = "../shape/visual/" + visualName + ".obj";
      const UnitBoxPart hull = unitBoxPart(physics::convexHullPart(control.mesh, 60));
      const std::string collisionName = model + "_" + link + "_collision_0.obj";
      writeFileAtomic(root / "shape" / "collision" / collisionName, hull.obj);
      collisionFile = "../shape/collision/" + collisionName;
      collisionScale = hull.scale;
    } else {
      rpy = rpyAlong(control.part.axis);
    }
    xml << "    <visual name=\"" << escapeXml(link) << "_visual\">\n      "
        << origin(Eigen::Vector3d::Zero(), rpy) << "\n      <geometry>"
        << geometryXml(control, visualFile, Eigen::Vector3d::Ones())
        << "</geometry>\n    </visual>\n    <collision name=\"" << escapeXml(link)
        << "_collision_0\">\n      " << origin(Eigen::Vector3d::Zero(), rpy)
        << "\n      <geometry>" << geometryXml(control, collisionFile, collisionScale)
        << "</geometry>\n    </collision>\n"
        << inertialXml(control.mass) << "  </link>\n";
  }
  return xml.str();
}

}  // namespace sagrid::exportdetail
