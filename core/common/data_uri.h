// URIs as glTF files write them: "data:" URIs that carry a buffer or image inline (base64), and
// relative references with percent-escapes ("my%20tex.png"). Used by the glTF reader
// (core/mesh/gltf_asset), which must open embedded and external buffers and images itself.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace sagrid {

// The bytes of a "data:[<mediatype>][;base64],<data>" URI; nullopt when `uri` is no data URI.
// Throws InvalidArgument for a data URI that is not base64 or whose base64 is malformed.
std::optional<std::string> dataUriBytes(std::string_view uri);

// The media type a data URI declares ("image/webp"), empty when it declares none or is no data URI.
std::string dataUriMediaType(std::string_view uri);

// `text` with every %XX escape replaced by its byte; a malformed escape is kept as written.
std::string percentDecoded(std::string_view text);

}  // namespace sagrid
