#include "core/export/omnigibson_export.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/ascii_case.h"
#include "core/common/atomic_file.h"
#include "core/common/contained_paths.h"
#include "core/common/error.h"
#include "core/common/json_number.h"
#include "core/common/staged_folder.h"
#include "core/export/export_frame.h"
#include "core/export/omnigibson_meta_links.h"
#include "core/export/simulator_geometry.h"
#include "core/export/urdf_controls.h"
#include "core/export/urdf_xml.h"
#include "core/export/xml_text.h"
#include "core/mesh/mesh_export.h"
#include "core/physics/convex_decomposition.h"

namespace sagrid {

namespace fs = std::filesystem;
using exportdetail::formatNumber;
using exportdetail::formatVector;
using exportdetail::inertialXml;
using exportdetail::kBaseLink;
using exportdetail::origin;
using exportdetail::unitBoxPart;
using exportdetail::UnitBoxPart;

namespace {

constexpr double kMetaLinkMass = 0.0001;  // what _create_urdf_meta_link gives meta links
constexpr double kMetaLinkInertia = 0.00001;

std::string metaLinksXml(const std::vector<exportdetail::MetaLink>& links) {
  std::ostringstream xml;
  for (const auto& link : links) {
    const std::string stem = link.linkName.substr(0, link.linkName.size() - 5);  // no "_link"
    xml << "  <joint name=\"" << stem << "_joint\" type=\"fixed\">\n    "
        << origin(link.position.cast<double>()) << "\n    <parent link=\"" << kBaseLink
        << "\"/>\n    <child link=\"" << link.linkName << "\"/>\n  </joint>\n"
        << "  <link name=\"" << link.linkName << "\">\n    <inertial>\n      <mass value=\""
        << formatNumber(kMetaLinkMass) << "\"/>\n      <inertia ixx=\""
        << formatNumber(kMetaLinkInertia) << "\" ixy=\"0\" ixz=\"0\" iyy=\""
        << formatNumber(kMetaLinkInertia) << "\" iyz=\"0\" izz=\"" << formatNumber(kMetaLinkInertia)
        << "\"/>\n    </inertial>\n  </link>\n";
  }
  return xml.str();
}

// nlohmann writes NaN and infinity as null; no such number may reach metadata.json.
void requireFiniteNumbers(const nlohmann::json& json) {
  if (json.is_number_float() && !std::isfinite(json.get<double>()))
    throw Error("internal error: a non-finite number reached metadata.json");
  if (json.is_structured())
    for (const auto& item : json) requireFiniteNumbers(item);
}

}  // namespace

SimulatorExport exportOmniGibson(const ObjectLabels& labels, const fs::path& meshPath,
                                 const fs::path& outDir, const ExportOptions& options,
                                 const fs::path& labelsPath) {
  const std::string id = exportdetail::objectId(labels, meshPath);
  exportdetail::SimulatorGeometry geometry =
      exportdetail::buildSimulatorGeometry(labels, meshPath, labelsPath, options);
  SimulatorExport result;
  result.warnings = std::move(geometry.warnings);

  ExportNames localNames;
  ExportNames& names = options.names ? *options.names : localNames;
  const std::string model = names.models.claim(id, result.warnings);
  if (labels.object.category.empty())
    result.warnings.push_back(id + ": no category; exported under the category 'object'");
  const std::string category = safeFileName(asciiLower(labels.object.category), 64, "object");
  StagedFolder staged(outDir / category / model);
  const fs::path root = staged.path();

  // Visual mesh: the imported mesh less its moving controls, z up in metres, as one OBJ with one MTL (the importer's
  // _force_asset_pipeline_materials allows one mtllib per OBJ) and its textures.
  Mesh visual = geometry.body;
  visual.fileUp = UpAxis::Z;
  // Material names become safe MTL names in encodeObj (no line breaks: issue 14).
  const std::string visualName = model + "_base_link_visual";
  fs::create_directories(root / "shape" / "visual");
  writeEncodedMeshFiles(encodeObj(visual, visualName), root / "shape" / "visual");

  std::ostringstream link;
  link << "  <link name=\"" << kBaseLink << "\">\n    <visual name=\"base_link_visual\">\n      "
       << origin(Eigen::Vector3d::Zero()) << "\n      <geometry><mesh filename=\"../shape/visual/"
       << visualName << ".obj\" scale=\"1 1 1\"/></geometry>\n    </visual>\n";
  fs::create_directories(root / "shape" / "collision");
  for (std::size_t i = 0; i < geometry.collisionParts.size(); ++i) {
    const UnitBoxPart part = unitBoxPart(geometry.collisionParts[i]);
    const std::string file = model + "_base_link_collision_" + std::to_string(i) + ".obj";
    writeFileAtomic(root / "shape" / "collision" / file, part.obj);
    link << "    <collision name=\"base_link_collision_" << i << "\">\n      "
         << origin(Eigen::Vector3d::Zero()) << "\n      <geometry><mesh filename=\"../shape/"
         << "collision/" << file << "\" scale=\"" << formatVector(part.scale)
         << "\"/></geometry>\n    </collision>\n";
  }
  link << inertialXml(geometry.mass) << "  </link>\n";
  const std::vector<exportdetail::MjcfSite> sites =
      exportdetail::simulatorSites(labels, geometry, result.warnings);
  link << exportdetail::controlLinksXml(geometry, sites, model, root);

  std::vector<exportdetail::SimulatorPoint> points;
  for (const auto& point : labels.affordances) {
    points.push_back({point.type,
                      exportdetail::toSimulatorFrame(labels, point.position, geometry.metersPerUnit),
                      std::nullopt});
  }
  const auto metaLinks =
      exportdetail::omnigibsonMetaLinks(points, options.legacyFluidSource, result.warnings);
  const std::string head = "<?xml version=\"1.0\"?>\n<robot name=\"" + model + "\">\n";
  fs::create_directories(root / "urdf");
  writeFileAtomic(root / "urdf" / (model + ".urdf"), head + link.str() + "</robot>\n");
  writeFileAtomic(root / "urdf" / (model + "_with_meta_links.urdf"),
                  head + link.str() + metaLinksXml(metaLinks) + "</robot>\n");

  // misc/metadata.json as record_obj_metadata_from_urdf writes it, plus the meta links.
  const Eigen::Vector3f size = geometry.bounds.sizes();
  const Eigen::Vector3f offset = geometry.bounds.center();
  nlohmann::json metadata = {
      {"bbox_size", {jsonNumber(size.x()), jsonNumber(size.y()), jsonNumber(size.z())}},
      {"base_link_offset",
       {jsonNumber(offset.x()), jsonNumber(offset.y()), jsonNumber(offset.z())}},
      {"link_tags", nlohmann::json::object()},
      {"object_parts", nlohmann::json::array()},
      {"orientations", nlohmann::json::array()},
      {"meta_links", exportdetail::metaLinksJson(metaLinks)},
      {"sagrid",
       {{"id", id},
        {"mesh_sha256", geometry.mesh.sha256},
        {"mass_kg", geometry.mass.mass},
        {"mass_source", geometry.massFromLabels ? "labels object.mass_kg" : "estimated"},
        {"tool", std::string("sagrid ") + SAGRID_VERSION}}}};
  requireFiniteNumbers(metadata);
  fs::create_directories(root / "misc");
  writeFileAtomic(root / "misc" / "metadata.json",
                  metadata.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  staged.commit();

  result.root = outDir / category / model;
  result.mainFile = result.root / "urdf" / (model + ".urdf");
  result.visualTriangles = static_cast<int>(geometry.mesh.triangles.size());  // body and controls
  result.collisionParts = static_cast<int>(geometry.collisionParts.size());
  result.massKg = geometry.mass.mass;
  if (labels.affordances.empty())
    result.warnings.push_back(id + ": no affordance points to export");
  return result;
}

}  // namespace sagrid
