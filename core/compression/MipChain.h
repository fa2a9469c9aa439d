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
// (RoughnessFold.h). For a colour map with alpha, an `alphaCutoff` above 0 keeps each level's
// share of texels at or above it (scaleAlphaToCoverage), so cut-outs do not thin away far off.
struct MipChainSpec {
  bool mipmaps = true;
  MipFilter filter = MipFilter::Box;
  bool foldNormalSpread = false;
  float alphaCutoff = 0.0f;
  bool operator==(const MipChainSpec&) const = default;
};

// Level 0 is `image` itself; the last level is 1x1.
std::vector<Image> buildMipChain(const Image& image, MapSlot slot,
                                 MipFilter filter = MipFilter::Box);

// One level down.
Image downsampleForSlot(const Image& image, MapSlot slot, MipFilter filter = MipFilter::Box);

int mipLevelCount(int width, int height);

// The share of texels whose alpha (the fourth channel) is at least `cutoff`; 0 without alpha.
double alphaCoverage(const Image& image, float cutoff);
// Scales `level`'s alpha (clamped to 1) so that its coverage of `cutoff` is `coverage`, as far
// as its texels allow (I. Castaño, "Computing Alpha Mipmaps", 2010, as NVIDIA Texture Tools'
// scaleAlphaToCoverage): averaging thins a cut-out's alpha, and an alpha-tested level would
// lose leaves and fences far away. The scale is exact (a quantile of the level's alphas), not a
// search; a level of N texels can only hit coverage to 1/N.
void scaleAlphaToCoverage(Image& level, float cutoff, double coverage);

}  // namespace relief::core::inline compression
