// The moving parts of a URDF export (OmniGibson): each toggle button's control part a child link
// of base_link on a revolute (knob, lever) or prismatic (button) joint with its limits and
// damping (control_geometry.h), named after its RoboCasa site (knob_front_left_link,
// knob_front_left_joint; handle_link, ...). Its visual is the part cut from the body (an OBJ with
// its materials), its collision the part's convex hull, its inertia from its volume; a printed
// key's disc is a thin cylinder. Meta links stay on base_link.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/export/robocasa_sites.h"
#include "core/export/simulator_geometry.h"

namespace sagrid::exportdetail {

// Writes the links' meshes under ROOT/shape/{visual,collision}; returns the joints and links.
std::string controlLinksXml(const SimulatorGeometry& geometry, const std::vector<MjcfSite>& sites,
                            const std::string& model, const std::filesystem::path& root);

}  // namespace sagrid::exportdetail
