// Text that goes into the XML files the exporters write (MJCF, URDF): names and paths that come
// from data are escaped, so an id holding <>"&' still gives well-formed XML (issue 14).
#pragma once

#include <string>
#include <string_view>

namespace sagrid::exportdetail {

// Escapes & < > " ' as entities; other control bytes (not allowed in XML 1.0) become '_'.
std::string escapeXml(std::string_view text);

}  // namespace sagrid::exportdetail
