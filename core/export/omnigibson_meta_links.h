// OmniGibson meta links for affordance points: the metadata.json "meta_links" entries and the
// link names, by the rules of the importer (BEHAVIOR-1K asset_conversion_utils.py):
//  - _add_meta_links_to_urdf: meta_links is {parent link: {type: {id: [ {position, orientation
//    (x y z w)} ]}}}, every type in _ALLOWED_META_TYPES, one entry per id for non-attachment
//    dimensionless types, links named meta__<parent>_<type>_<id>_<subid>_link on fixed joints;
//  - import_obj_metadata: the name is split with rsplit("_", 3), so type, id and subid hold no
//    underscore (ids here are digits);
//  - _generate_meshes_for_primitive_meta_links: togglebutton is a primitive with "type" and
//    "size" (a sphere of radius size[0]); particlesource is always the cylinder of radius 0.0125 m
//    and height 0.05 m hanging below the link origin, particles along -z.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/export/robocasa_sites.h"

namespace sagrid::exportdetail {

inline constexpr const char* kBaseLink = "base_link";
inline constexpr double kToggleButtonRadius = 0.02;      // metres: a fingertip-sized volume
inline constexpr double kParticleSourceRadius = 0.0125;  // what OmniGibson builds
inline constexpr double kParticleSourceHeight = 0.05;

struct MetaLink {
  std::string type;      // OmniGibson type, e.g. "heatsource"
  std::string id;        // letters and digits
  std::string linkName;  // meta__base_link_<type>_<id>_0_link
  Eigen::Vector3f position;
  nlohmann::json entry;  // the metadata.json entry
};

// Meta links for points in OmniGibson's frame (z up, metres). Points whose type OmniGibson does
// not know are left out with a warning.
std::vector<MetaLink> omnigibsonMetaLinks(const std::vector<SimulatorPoint>& points,
                                          bool legacyFluidSource,
                                          std::vector<std::string>& warnings);

// {"base_link": {type: {id: [entry]}}} (an empty object when there are none).
nlohmann::json metaLinksJson(const std::vector<MetaLink>& links);

}  // namespace sagrid::exportdetail
