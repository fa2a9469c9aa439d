// TextureCache: the GPU copies of materials' maps. An image is uploaded once however many
// materials use it (the viewport's A/B comparison shares maps), stays until no material uses
// it, and an empty slot gets a neutral 1x1 texture so the shaders never branch on missing maps.
#pragma once

#include "core/Material.h"

#include <QOpenGLPixelTransferOptions>
#include <QOpenGLTexture>

#include <array>
#include <initializer_list>
#include <map>
#include <memory>
#include <utility>

namespace relief::renderer {

class TextureCache {
 public:
  // Needs a current context. Uploads on first use.
  QOpenGLTexture& texture(const core::Material& material, core::MapSlot slot);
  // Frees the uploads that none of `materials` uses any more.
  void releaseUnused(std::initializer_list<const core::Material*> materials);
  void release();

 private:
  using Key = std::pair<const core::Image*, core::MapSlot>;
  struct Entry {
    std::shared_ptr<const core::Image> image;  // keeps the key's address from being reused
    std::unique_ptr<QOpenGLTexture> texture;
  };
  std::map<Key, Entry> m_uploads;
  std::array<std::unique_ptr<QOpenGLTexture>, core::kMapSlotCount> m_neutral;
};

// Creates the texture for one slot's image (rows flipped so UV (0,0) is the image's lower-left
// corner, full mip chain). Colour maps use sRGB storage so the sampler decodes before filtering;
// data maps keep their precision (16-bit normals, 32-bit float heights).
std::unique_ptr<QOpenGLTexture> createMapTexture(const core::Image& image, core::MapSlot slot);

}  // namespace relief::renderer
