#include "core/export/xml_text.h"

namespace sagrid::exportdetail {

std::string escapeXml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default: {
        const auto byte = static_cast<unsigned char>(c);
        out.push_back(byte < 0x20 && c != '\t' && c != '\n' && c != '\r' ? '_' : c);
      }
    }
  }
  return out;
}

}  // namespace sagrid::exportdetail
