#include "core/export/urdf_xml.h"

#include <sstream>

#include "core/export/export_frame.h"

namespace sagrid::exportdetail {

UnitBoxPart unitBoxPart(const physics::ConvexPart& part) {
  Eigen::AlignedBox3d box;
  for (const auto& v : part.vertices) box.extend(v.cast<double>());
  UnitBoxPart out;
  out.scale = box.sizes().cwiseMax(1e-6);  // parts span a volume; guard the division anyway
  std::ostringstream obj;
  obj << "# convex collision part written by sagrid (unit bounding box; URDF scale restores it)\n";
  for (const auto& v : part.vertices)
    obj << "v " << formatVector(v.cast<double>().cwiseQuotient(out.scale)) << "\n";
  for (const auto& t : part.triangles)
    obj << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  out.obj = obj.str();
  return out;
}

std::string origin(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy) {
  return "<origin xyz=\"" + formatVector(xyz) + "\" rpy=\"" + formatVector(rpy) + "\"/>";
}

std::string inertialXml(const physics::MassProperties& mass) {
  const Eigen::Matrix3d& I = mass.inertia;
  std::ostringstream xml;
  xml << "    <inertial>\n      " << origin(mass.centerOfMass) << "\n      <mass value=\""
      << formatNumber(mass.mass) << "\"/>\n      <inertia ixx=\"" << formatNumber(I(0, 0))
      << "\" ixy=\"" << formatNumber(I(0, 1)) << "\" ixz=\"" << formatNumber(I(0, 2)) << "\" iyy=\""
      << formatNumber(I(1, 1)) << "\" iyz=\"" << formatNumber(I(1, 2)) << "\" izz=\""
      << formatNumber(I(2, 2)) << "\"/>\n    </inertial>\n";
  return xml.str();
}

}  // namespace sagrid::exportdetail
