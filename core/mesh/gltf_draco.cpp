#include "core/mesh/gltf_draco.h"

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include "core/common/error.h"

namespace sagrid {

DecodedDracoPrimitive decodeDracoPrimitive(std::string_view bytes,
                                           const std::map<std::string, int>& attributeIds) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  const auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
  if (!type.ok() || type.value() != draco::TRIANGULAR_MESH) {
    throw InvalidArgument("its Draco data is not a compressed triangle mesh (corrupt or truncated)");
  }
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) {
    throw InvalidArgument("its Draco data does not decode (" + decoded.status().error_msg_string() +
                          "; corrupt or truncated)");
  }
  const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  DecodedDracoPrimitive out;
  out.points = mesh->num_points();
  out.indices.reserve(static_cast<std::size_t>(mesh->num_faces()) * 3);
  for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
    for (const draco::PointIndex p : mesh->face(f)) out.indices.push_back(p.value());
  }
  for (const auto& [name, id] : attributeIds) {
    const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(static_cast<std::uint32_t>(id));
    if (!attribute) {
      throw InvalidArgument("its Draco data has no attribute " + std::to_string(id) + " for " + name);
    }
    DracoAttribute values;
    values.components = attribute->num_components();
    if (values.components < 1 || values.components > 4) {
      throw InvalidArgument("its Draco attribute " + name + " has " + std::to_string(values.components) + " components");
    }
    values.values.resize(out.points * values.components);
    float element[4] = {0, 0, 0, 0};
    for (draco::PointIndex p(0); p < mesh->num_points(); ++p) {
      if (!attribute->ConvertValue<float>(attribute->mapped_index(p), static_cast<int8_t>(values.components), element)) {
        throw InvalidArgument("its Draco attribute " + name + " cannot be read as numbers");
      }
      std::copy_n(element, values.components, values.values.begin() + static_cast<std::size_t>(p.value()) * values.components);
    }
    out.attributes[name] = std::move(values);
  }
  return out;
}

}  // namespace sagrid
