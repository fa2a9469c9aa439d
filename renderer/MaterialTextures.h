// MaterialTextures: the GPU copies of a material's maps. Re-uploads a slot only when its image
// changed (shared-pointer identity), and binds a neutral 1x1 texture for empty slots so the
// shaders never branch on missing maps.
#pragma once

#include "core/Material.h"

#include <QOpenGLPixelTransferOptions>
#include <QOpenGLTexture>

#include <array>
#include <memory>

namespace relief::renderer {

class MaterialTextures {
 public:
  // Needs a current context. Returns true when any texture changed.
  bool sync(const core::Material& material);
  // Binds slot i to texture unit firstUnit + i.
  void bind(int firstUnit);
  void release();

 private:
  std::array<std::unique_ptr<QOpenGLTexture>, core::kMapSlotCount> m_textures;
  // What each texture was made from; null when it holds the neutral default.
  std::array<std::shared_ptr<const core::Image>, core::kMapSlotCount> m_sources;
  std::array<bool, core::kMapSlotCount> m_initialised{};
};

// Creates the texture for one slot's image (rows flipped so UV (0,0) is the image's lower-left
// corner, full mip chain). Colour maps use sRGB storage so the sampler decodes before filtering;
// data maps keep their precision (16-bit normals, 32-bit float heights).
std::unique_ptr<QOpenGLTexture> createMapTexture(const core::Image& image, core::MapSlot slot);

}  // namespace relief::renderer
