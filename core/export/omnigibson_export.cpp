#include "core/export/omnigibson_export.h"

#include <cctype>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/export/export_frame.h"

namespace sagrid {

namespace fs = std::filesystem;
using exportdetail::formatNumber;

namespace {
constexpr const char* kBaseLink = "base_link";
constexpr double kToggleSphereRadius = 0.01;  // metres; a fingertip-sized button volume

std::string xyz(const Eigen::Vector3f& p) {
  return formatNumber(p.x()) + " " + formatNumber(p.y()) + " " + formatNumber(p.z());
}
}  // namespace

const char* omnigibsonMetaLinkKind(const std::string& affordanceType) {
  return affordanceType == "togglebutton" ? "sphere" : "point";
}

std::string omnigibsonId(const std::string& text) {
  std::string id;
  for (unsigned char c : text) {
    if (std::isalnum(c)) id.push_back(static_cast<char>(std::tolower(c)));
  }
  return id.empty() ? "object" : id;
}

SimulatorExport exportOmniGibson(const ObjectLabels& labels, const fs::path& meshPath,
                                 const fs::path& outDir) {
  const std::string id = omnigibsonId(exportdetail::objectId(labels, meshPath));
  SimulatorExport result;
  result.root = outDir / id;
  const fs::path copied =
      exportdetail::copyMeshWithDependencies(meshPath, result.root / "shape" / "visual");
  const std::string meshRef = "../shape/visual/" + copied.filename().string();
  const double scale = metersPerUnit(labels);
  // The file's up axis is turned to OmniGibson's +z (a y-up file: +90 degrees about x).
  const std::string rpy = exportdetail::uprightRollPitchYaw(labels);

  std::ostringstream urdf;
  urdf << "<?xml version=\"1.0\"?>\n<robot name=\"" << id << "\">\n";
  urdf << "  <link name=\"" << kBaseLink << "\">\n";
  for (const char* part : {"visual", "collision"}) {
    urdf << "    <" << part << ">\n      <origin xyz=\"0 0 0\" rpy=\"" << rpy << "\"/>\n"
         << "      <geometry><mesh filename=\"" << meshRef << "\" scale=\"" << formatNumber(scale)
         << " " << formatNumber(scale) << " " << formatNumber(scale) << "\"/></geometry>\n    </"
         << part << ">\n";
  }
  urdf << "  </link>\n";

  nlohmann::json metaLinks = nlohmann::json::object();
  std::map<std::string, int> perType;
  for (const auto& point : labels.affordances) {
    const std::string type = omnigibsonId(point.type);
    const std::string metaId = std::to_string(perType[type]++);
    const std::string link =
        std::string("meta__") + kBaseLink + "_" + type + "_" + metaId + "_0_link";
    const Eigen::Vector3f p = exportdetail::toSimulatorFrame(labels, point.position);
    const std::string kind = omnigibsonMetaLinkKind(point.type);
    urdf << "  <link name=\"" << link << "\">\n";
    if (kind == "sphere") {
      urdf << "    <visual><geometry><sphere radius=\"" << formatNumber(kToggleSphereRadius)
           << "\"/></geometry></visual>\n";
    }
    urdf << "  </link>\n  <joint name=\"" << link << "_joint\" type=\"fixed\">\n"
         << "    <parent link=\"" << kBaseLink << "\"/>\n    <child link=\"" << link << "\"/>\n"
         << "    <origin xyz=\"" << xyz(p) << "\" rpy=\"0 0 0\"/>\n  </joint>\n";
    nlohmann::json entry = {
        {"type", kind}, {"position", {p.x(), p.y(), p.z()}}, {"orientation", {0.0, 0.0, 0.0, 1.0}}};
    if (kind == "sphere")
      entry["size"] = {kToggleSphereRadius, kToggleSphereRadius, kToggleSphereRadius};
    metaLinks[kBaseLink][type][metaId] = nlohmann::json::array({entry});
  }
  urdf << "</robot>\n";

  result.mainFile = result.root / "urdf" / (id + ".urdf");
  fs::create_directories(result.mainFile.parent_path());
  writeFileAtomic(result.mainFile, urdf.str());
  nlohmann::json metadata = {{"meta_links", metaLinks},
                             {"category", labels.object.category},
                             {"source",
                              {{"mesh", meshPath.filename().string()},
                               {"sha256", labels.object.sha256},
                               {"tool", std::string("sagrid ") + SAGRID_VERSION}}}};
  fs::create_directories(result.root / "misc");
  writeFileAtomic(result.root / "misc" / "metadata.json", metadata.dump(2) + "\n");
  if (labels.affordances.empty())
    result.warnings.push_back(id + ": no affordance points to export");
  return result;
}

}  // namespace sagrid
