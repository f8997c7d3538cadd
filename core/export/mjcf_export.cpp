#include "core/export/mjcf_export.h"

#include <cctype>
#include <map>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/export/export_frame.h"

namespace sagrid {

namespace fs = std::filesystem;
using exportdetail::formatNumber;

namespace {
constexpr double kSiteRadius = 0.008;  // metres

std::string rgbaFor(const std::string& type) {
  if (type == "heatsource") return "1 0.4 0.1 0.6";
  if (type == "fluidsource") return "0.2 0.6 1 0.6";
  if (type == "togglebutton") return "0.3 0.9 0.35 0.6";
  return "0.9 0.9 0.2 0.6";
}

std::string siteName(const std::string& type, int index) {
  std::string name;
  for (unsigned char c : type)
    name.push_back(std::isalnum(c) ? static_cast<char>(std::tolower(c)) : '_');
  return name + "_" + std::to_string(index);
}
}  // namespace

SimulatorExport exportMjcf(const ObjectLabels& labels, const fs::path& meshPath,
                           const fs::path& outDir) {
  const std::string id = exportdetail::objectId(labels, meshPath);
  SimulatorExport result;
  result.root = outDir / id;
  const fs::path copied = exportdetail::copyMeshWithDependencies(meshPath, result.root);
  std::string ext = copied.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".obj" && ext != ".stl") {
    result.warnings.push_back(copied.filename().string() +
                              ": MuJoCo loads only OBJ and STL meshes; convert it "
                              "before loading " +
                              id + ".xml");
  }
  const double s = metersPerUnit(labels);
  std::ostringstream xml;
  xml << "<mujoco model=\"" << id << "\">\n  <compiler angle=\"radian\"/>\n  <asset>\n"
      << "    <mesh name=\"" << id << "_mesh\" file=\"" << copied.filename().string()
      << "\" scale=\"" << formatNumber(s) << " " << formatNumber(s) << " " << formatNumber(s)
      << "\"/>\n  </asset>\n"
      << "  <worldbody>\n    <body name=\"object\">\n";
  // The file's up axis is turned to +z (a y-up file: +90 degrees about x).
  const std::string upright = exportdetail::uprightQuaternion(labels);
  const std::string quat = upright.empty() ? "" : " quat=\"" + upright + "\"";
  xml << "      <geom name=\"" << id << "_visual\" type=\"mesh\" mesh=\"" << id << "_mesh\"" << quat
      << " contype=\"0\" conaffinity=\"0\" group=\"1\"/>\n";
  std::map<std::string, int> perType;
  for (const auto& point : labels.affordances) {
    const Eigen::Vector3f p = exportdetail::toSimulatorFrame(labels, point.position);
    xml << "      <site name=\"" << siteName(point.type, perType[point.type]++)
        << "\" type=\"sphere\" pos=\"" << formatNumber(p.x()) << " " << formatNumber(p.y()) << " "
        << formatNumber(p.z()) << "\" size=\"" << formatNumber(kSiteRadius) << "\" rgba=\""
        << rgbaFor(point.type) << "\" group=\"3\"/>\n";
  }
  xml << "    </body>\n  </worldbody>\n</mujoco>\n";
  result.mainFile = result.root / (id + ".xml");
  writeFileAtomic(result.mainFile, xml.str());
  if (labels.affordances.empty())
    result.warnings.push_back(id + ": no affordance points to export");
  return result;
}

}  // namespace sagrid
