// Material; see Material.h.
#include "core/material/Material.h"

namespace relief::core::inline material {

Material::Material() : m_parameters(defaultParameterValues()) {}

void Material::setMap(MapSlot slot, std::shared_ptr<const Image> image, std::string sourcePath,
                      int sourceChannel) {
  if (image && image->colorSpace() != mapSlotColorSpace(slot)) {
    auto retagged = std::make_shared<Image>(*image);
    retagged->setColorSpace(mapSlotColorSpace(slot));
    image = std::move(retagged);
  }
  m_maps[std::size_t(slot)] =
      MaterialMap{std::move(image), std::move(sourcePath), sourceChannel, nullptr};
}

void Material::setCompressedMap(MapSlot slot, std::shared_ptr<const CompressedTexture> texture,
                                std::shared_ptr<const Image> decoded) {
  std::string sourcePath = map(slot).sourcePath;
  setMap(slot, std::move(decoded), std::move(sourcePath), map(slot).sourceChannel);
  m_maps[std::size_t(slot)].compressed = std::move(texture);
}

void Material::setParameter(ParamId id, double value) {
  m_parameters[std::size_t(id)] = sanitizeOptionValue(parameterSpec(id), value);
}

}  // namespace relief::core::inline material
