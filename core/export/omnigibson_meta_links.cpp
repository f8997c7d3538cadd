#include "core/export/omnigibson_meta_links.h"

#include <map>

#include "core/common/json_number.h"
#include "core/export/export_frame.h"
#include "core/export/omnigibson_export.h"

namespace sagrid {

std::string omnigibsonMetaLinkType(const std::string& affordanceType, bool legacyFluidSource) {
  if (affordanceType == "heatsource" || affordanceType == "togglebutton") return affordanceType;
  if (affordanceType == "fluidsource" || affordanceType == "particlesource")
    return legacyFluidSource ? "fluidsource" : "particlesource";
  return "";
}

namespace exportdetail {

std::vector<MetaLink> omnigibsonMetaLinks(const std::vector<SimulatorPoint>& points,
                                          bool legacyFluidSource,
                                          std::vector<std::string>& warnings) {
  std::vector<MetaLink> links;
  std::map<std::string, int> perType;
  for (const auto& point : points) {
    const std::string type = omnigibsonMetaLinkType(point.type, legacyFluidSource);
    if (type.empty()) {
      warnings.push_back("affordance type '" + point.type.substr(0, 40) +
                         "' has no OmniGibson meta link; left out");
      continue;
    }
    MetaLink link;
    link.type = type;
    link.id = std::to_string(perType[type]++);
    link.linkName = std::string("meta__") + kBaseLink + "_" + type + "_" + link.id + "_0_link";
    link.position = point.position;
    const auto& p = point.position;
    link.entry = {{"position", {jsonNumber(p.x()), jsonNumber(p.y()), jsonNumber(p.z())}},
                  {"orientation", {0.0, 0.0, 0.0, 1.0}}};
    if (type == "togglebutton") {
      link.entry["type"] = "sphere";
      link.entry["size"] = {kToggleButtonRadius, kToggleButtonRadius, kToggleButtonRadius};
    } else if (type == "particlesource" || type == "fluidsource") {
      link.entry["type"] = "cylinder";
      link.entry["size"] = {kParticleSourceRadius, kParticleSourceRadius, kParticleSourceHeight};
    }
    links.push_back(std::move(link));
  }
  return links;
}

nlohmann::json metaLinksJson(const std::vector<MetaLink>& links) {
  nlohmann::json json = nlohmann::json::object();
  for (const auto& link : links)
    json[kBaseLink][link.type][link.id] = nlohmann::json::array({link.entry});
  return json;
}

}  // namespace exportdetail
}  // namespace sagrid
