// Mipmap chains for maps: each level half the size of the one above (rounded down, at least
// 1), filtered from the level above. Box: by area, so odd sizes weigh partial texels correctly.
// Kaiser: a Kaiser-windowed sinc three destination texels wide (alpha 4, NVIDIA Texture Tools'
// default mip filter), wrapping around the edges as tiled maps do: sharper levels without the
// box's aliasing of detail near the new level's Nyquist limit. Colour is filtered in linear
// light and re-encoded to sRGB (clamped to 0..1: the sinc's lobes overshoot); normals are
// decoded to vectors, filtered and renormalised; heights and other data are filtered as stored.
#pragma once

#include "core/image/Image.h"
#include "core/material/MapSlot.h"

#include <optional>
#include <string_view>
#include <vector>

namespace relief::core::inline compression {

enum class MipFilter { Box, Kaiser };
std::string_view mipFilterName(MipFilter filter);
std::optional<MipFilter> findMipFilter(std::string_view name);

// The chain a map is sampled with, as a game ships it: level 0 alone (no mipmaps: the sampler
// aliases wherever a texel is smaller than a pixel), or every level down to 1x1 by `filter`.
// For a roughness map, `foldNormalSpread` widens each level by the normal map's spread under it
// (RoughnessFold.h).
struct MipChainSpec {
  bool mipmaps = true;
  MipFilter filter = MipFilter::Box;
  bool foldNormalSpread = false;
  bool operator==(const MipChainSpec&) const = default;
};

// Level 0 is `image` itself; the last level is 1x1.
std::vector<Image> buildMipChain(const Image& image, MapSlot slot,
                                 MipFilter filter = MipFilter::Box);

// One level down.
Image downsampleForSlot(const Image& image, MapSlot slot, MipFilter filter = MipFilter::Box);

int mipLevelCount(int width, int height);

}  // namespace relief::core::inline compression
