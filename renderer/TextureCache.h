// TextureCache: the GPU copies of materials' maps. An image is uploaded once however many
// materials use it (the viewport's A/B comparison shares maps), stays until no material uses
// it, and an empty slot gets a neutral 1x1 texture so the shaders never branch on missing maps.
#pragma once

#include "core/compression/MipChain.h"
#include "core/material/Material.h"
#include "core/tracing/ConeMap.h"

#include <QOpenGLPixelTransferOptions>
#include <QOpenGLTexture>

#include <array>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <utility>

namespace relief::renderer {

// What the exact tracers walk is derived from the height the shaders read: the image (the
// height map, or the normal map when the height is packed in its alpha), a compression preview of
// it, and whether it holds depths.
struct TracedHeightKey {
  const core::Image* image;
  const core::CompressedTexture* compressed;  // a preview's texels are what is bounded
  bool packed;
  bool depth;
  auto operator<=>(const TracedHeightKey&) const = default;
};
TracedHeightKey tracedHeightKey(const core::Material& material);

// The cone map (core/tracing/ConeMap.h) of the height the shaders read for `material` (a
// compression preview's decoded texels). No GL: safe off the GUI thread.
core::ConeMap buildTracedConeMap(const core::Material& material);

class TextureCache {
 public:
  // Needs a current context. Uploads on first use; an uncompressed map with the mip chain `chain`
  // (rebuilt when the chain asked for changes), a compression preview with its own levels.
  QOpenGLTexture& texture(const core::Material& material, core::MapSlot slot,
                          const core::MipChainSpec& chain = {});
  // For a slot holding a compressed preview: whether its blocks went to the GPU as they are
  // (false: the driver lacks the format and the decoded map was uploaded). Empty otherwise.
  std::optional<bool> uploadedNatively(const core::Material& material, core::MapSlot slot);
  // Off: compressed previews are always decoded by core and uploaded level by level (to compare
  // the driver's decoding with ours, and for tests). On by default.
  void setNativeCompressedUploads(bool native);
  bool nativeCompressedUploads() const { return m_nativeCompressed; }
  // The maximum-mipmap pyramid (core/tracing/MaxMipPyramid.h) of the height the shaders read
  // (the height map, or the normal map's alpha when packed, inverted for depth maps; a
  // compression preview's decoded texels), built on first use: R32F, nearest, one level each.
  QOpenGLTexture& heightPyramid(const core::Material& material);
  // The cone map (core/tracing/ConeMap.h) of the same height, for the cone technique: R32F, one
  // level, nearest; built on first use, once per height map (a 1024x1024 map takes tens of
  // milliseconds, a 4096x4096 one seconds).
  QOpenGLTexture& coneMap(const core::Material& material);
  // Deferred (the viewport): coneMap() is not to be called for a height whose cone map is not
  // ready; the owner builds it off the GUI thread (buildTracedConeMap) and hands it over with
  // provideConeMap. Not deferred (the CLI, tests): coneMap() builds it on the spot.
  void setDeferredConeMaps(bool deferred) { m_deferredConeMaps = deferred; }
  bool coneMapReady(const core::Material& material) const;
  void provideConeMap(const core::Material& material, const core::ConeMap& cones);
  // Frees the uploads that none of `materials` uses any more.
  void releaseUnused(std::initializer_list<const core::Material*> materials);
  void release();

 private:
  using Key = std::pair<const core::Image*, core::MapSlot>;
  struct Entry {
    std::shared_ptr<const core::Image> image;  // keeps the key's address from being reused
    std::unique_ptr<QOpenGLTexture> texture;
    bool compressed = false;   // a compression preview (native blocks or decoded levels)
    bool native = false;       // compressed blocks uploaded as they are
    core::MipChainSpec chain;  // of an uncompressed map's texture
    std::shared_ptr<const core::Image> spreadNormals;  // a folded roughness chain's normal map
  };
  std::map<Key, Entry> m_uploads;
  struct TraceEntry {
    std::shared_ptr<const core::Image> image;  // keeps the key's address from being reused
    std::shared_ptr<const core::CompressedTexture> compressed;
    std::unique_ptr<QOpenGLTexture> pyramid;
    std::unique_ptr<QOpenGLTexture> cones;
    // The height texels the shaders fetch (a compression preview's decoded ones).
    std::shared_ptr<const core::Image> texels() const;
  };
  TraceEntry& traceEntry(const TracedHeightKey& key, const core::Material& material);
  std::map<TracedHeightKey, TraceEntry> m_traces;
  bool m_deferredConeMaps = false;
  std::array<std::unique_ptr<QOpenGLTexture>, core::kMapSlotCount> m_neutral;
  bool m_nativeCompressed = true;
};

// Creates the texture for one slot's image (rows top first, as files and compressed blocks store
// them; the shaders flip V, see material_inputs.glsl). Colour maps use sRGB storage so the sampler
// decodes before filtering; data maps keep their precision (16-bit normals, 32-bit float heights).
// The mip levels are core's (core/compression/MipChain.h: colour averaged in linear light, normals
// renormalised, box or Kaiser), the chain a compressed export of the map holds, not the driver's
// glGenerateMipmap, whose filter the GL leaves to the implementation.
// A roughness map's chain with `chain.foldNormalSpread` widens its levels by the spread of
// `spreadNormals` (core/compression/RoughnessFold.h).
std::unique_ptr<QOpenGLTexture> createMapTexture(const core::Image& image, core::MapSlot slot,
                                                 const core::MipChainSpec& chain = {},
                                                 const core::Image* spreadNormals = nullptr);
// The same for a compressed preview decoded by core: every level of the file decoded and uploaded
// as the slot's format (so the mip levels are the compressed ones, not regenerated).
std::unique_ptr<QOpenGLTexture> createDecodedTexture(const core::CompressedTexture& compressed,
                                                     core::MapSlot slot);

}  // namespace relief::renderer
