#include "core/export/mjcf_export.h"

#include <algorithm>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/contained_paths.h"
#include "core/export/export_frame.h"
#include "core/export/mjcf_controls.h"
#include "core/export/robocasa_sites.h"
#include "core/export/simulator_geometry.h"
#include "core/common/staged_folder.h"
#include "core/export/stl_file.h"
#include "core/export/xml_text.h"
#include "core/physics/convex_decomposition.h"

namespace sagrid {

namespace fs = std::filesystem;
using exportdetail::escapeXml;
using exportdetail::formatNumber;
using exportdetail::formatVector;

namespace {

constexpr double kMinRegionHalfSize = 0.0005;  // metres; MuJoCo refuses zero-sized boxes

void writeAssets(std::ostringstream& xml, const exportdetail::SimulatorGeometry& geometry,
                 const std::vector<std::string>& controlBodies, const fs::path& folder) {
  fs::create_directories(folder / "meshes");
  xml << "  <asset>\n";
  for (const auto& part : geometry.visualParts) {
    writeFileAtomic(folder / "meshes" / (part.name + ".stl"),
                    exportdetail::encodeBinaryStl(part.mesh));
    xml << "    <material name=\"" << part.name << "\" rgba=\""
        << formatVector(part.color.cast<double>()) << " 1\"/>\n"
        << "    <mesh name=\"" << part.name << "\" file=\"meshes/" << part.name << ".stl\"/>\n";
  }
  for (std::size_t i = 0; i < geometry.collisionParts.size(); ++i) {
    const std::string name = "collision_" + std::to_string(i);
    writeFileAtomic(folder / "meshes" / (name + ".stl"),
                    exportdetail::encodeBinaryStl(physics::toMesh(geometry.collisionParts[i])));
    xml << "    <mesh name=\"" << name << "\" file=\"meshes/" << name << ".stl\"/>\n";
  }
  exportdetail::writeControlAssets(xml, geometry.controls, controlBodies, folder);
  xml << "  </asset>\n";
}

void writeInertial(std::ostringstream& xml, const physics::MassProperties& mass) {
  const Eigen::Quaterniond& q = mass.principalAxes;
  xml << "      <inertial pos=\"" << formatVector(mass.centerOfMass) << "\" quat=\""
      << formatNumber(q.w()) << " " << formatNumber(q.x()) << " " << formatNumber(q.y()) << " "
      << formatNumber(q.z()) << "\" mass=\"" << formatNumber(mass.mass) << "\" diaginertia=\""
      << formatVector(mass.principalMoments) << "\"/>\n";
}

void writeGeoms(std::ostringstream& xml, const exportdetail::SimulatorGeometry& geometry) {
  for (const auto& part : geometry.visualParts) {
    xml << "      <geom name=\"" << part.name << "\" class=\"visual\" mesh=\"" << part.name
        << "\" material=\"" << part.name << "\"/>\n";
  }
  for (std::size_t i = 0; i < geometry.collisionParts.size(); ++i) {
    const std::string name = "collision_" + std::to_string(i);
    xml << "      <geom name=\"" << name << "\" class=\"collision\" mesh=\"" << name << "\"/>\n";
  }
  // RoboCasa's fixtures carry their bounding box as the region geom "reg_main".
  const Eigen::Vector3d center = geometry.bounds.center().cast<double>();
  const Eigen::Vector3d half =
      (0.5 * geometry.bounds.sizes().cast<double>()).cwiseMax(kMinRegionHalfSize);
  xml << "      <geom name=\"reg_main\" type=\"box\" pos=\"" << formatVector(center) << "\" size=\""
      << formatVector(half)
      << "\" contype=\"0\" conaffinity=\"0\" group=\"3\" rgba=\"0 1 0 0\"/>\n";
}

// Burners and other points' sites in "object", each control's site in its body, each water site
// in its spout body.
// Returns the bodies of the buttons that drive a switch (exportdetail::writeSwitchBody).
std::vector<std::string> writeBodies(std::ostringstream& xml,
                                     const exportdetail::SimulatorGeometry& geometry,
                                     const std::vector<exportdetail::MjcfSite>& sites,
                                     const std::vector<std::string>& controlBodies) {
  std::vector<bool> inControl(sites.size(), false);
  for (const auto& control : geometry.controls) inControl[control.point] = true;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    if (!inControl[i] && sites[i].affordanceType != "fluidsource")
      exportdetail::writeSite(xml, sites[i], "      ");
  }
  const bool oneHandle =
      std::none_of(sites.begin(), sites.end(), [](const auto& s) { return s.name == "handle_temp"; });
  std::set<std::string> burnerSites;
  for (const auto& site : sites)
    if (site.affordanceType == "heatsource") burnerSites.insert(site.name);
  std::vector<std::string> switched;
  for (std::size_t c = 0; c < geometry.controls.size(); ++c) {
    const auto& control = geometry.controls[c];
    const std::string& body = controlBodies[c];
    const bool drivesSwitch = exportdetail::pressDrivesSwitch(control, body, burnerSites);
    exportdetail::writeControlBody(
        xml, control, body, sites[control.point],
        exportdetail::controlJoints(control, body, oneHandle && body == "handle", drivesSwitch));
    if (drivesSwitch) {
      exportdetail::writeSwitchBody(xml, control, body);
      switched.push_back(body);
    }
  }
  for (const auto& site : sites)
    if (site.affordanceType == "fluidsource") exportdetail::writeSpoutBody(xml, site);
  return switched;
}

}  // namespace

SimulatorExport exportMjcf(const ObjectLabels& labels, const fs::path& meshPath,
                           const fs::path& outDir, const ExportOptions& options,
                           const fs::path& labelsPath) {
  const std::string id = exportdetail::objectId(labels, meshPath);
  ExportNames localNames;
  ExportNames& names = options.names ? *options.names : localNames;
  const std::string folderName = names.folders.claim(id);

  exportdetail::SimulatorGeometry geometry =
      exportdetail::buildSimulatorGeometry(labels, meshPath, labelsPath, options);
  SimulatorExport result;
  result.warnings = std::move(geometry.warnings);
  StagedFolder staged(outDir / folderName);
  const std::vector<exportdetail::MjcfSite> sites =
      exportdetail::simulatorSites(labels, geometry, result.warnings);
  std::vector<std::string> controlBodies;
  for (const auto& control : geometry.controls) controlBodies.push_back(sites[control.point].name);

  std::ostringstream xml;
  xml << "<mujoco model=\"" << escapeXml(id) << "\">\n"
      << "  <compiler angle=\"radian\" balanceinertia=\"true\"/>\n"
      << "  <default>\n"
      << "    <default class=\"visual\"><geom type=\"mesh\" contype=\"0\" conaffinity=\"0\" "
         "group=\"1\"/></default>\n"
      << "    <default class=\"collision\"><geom type=\"mesh\" group=\"0\" "
         "rgba=\"0.5 0.5 0.5 1\"/></default>\n"
      << "  </default>\n";
  writeAssets(xml, geometry, controlBodies, staged.path());
  // RoboCasa's nesting: worldbody > body > body name="object" (its sites at ./body/body/site,
  // its controls' joints at ./body/body/body/joint).
  xml << "  <worldbody>\n  <body>\n    <body name=\"object\">\n";
  writeInertial(xml, geometry.mass);
  writeGeoms(xml, geometry);
  const std::vector<std::string> switched = writeBodies(xml, geometry, sites, controlBodies);
  xml << "    </body>\n  </body>\n  </worldbody>\n";
  exportdetail::writeContactExclusions(xml, controlBodies);
  exportdetail::writeSwitchEqualities(xml, switched);
  xml << "</mujoco>\n";
  writeFileAtomic(staged.path() / (folderName + ".xml"), xml.str());
  staged.commit();

  result.root = outDir / folderName;
  result.mainFile = result.root / (folderName + ".xml");
  for (const auto& part : geometry.visualParts)
    result.visualTriangles += static_cast<int>(part.mesh.triangles.size());
  for (const auto& control : geometry.controls)
    result.visualTriangles += static_cast<int>(control.mesh.triangles.size());
  result.collisionParts = static_cast<int>(geometry.collisionParts.size());
  result.massKg = geometry.mass.mass;
  if (labels.affordances.empty())
    result.warnings.push_back(id + ": no affordance points to export");
  return result;
}

}  // namespace sagrid
