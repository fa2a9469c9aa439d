// Channel packing: the height into the normal map's alpha (references 001 and 003: one RGBA
// texture, one fetch), any channel swizzle between maps, and auto-levels for heights with the
// applied range recorded so the material's height scale can compensate.
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"

#include <string>
#include <vector>

namespace relief::core::inline generators {

struct LevelsRange {
  double low = 0.0;   // input value mapped to 0
  double high = 1.0;  // input value mapped to 1
};

// Stretches the first channel to [0, 1]; returns the range it had. A constant image is left
// as it is (range low == high).
LevelsRange autoLevels(Image& height);

// How a material keeps the same relief after its height map was auto-levelled from `range`:
// s = h * scale + bias with h = low + h' (high - low) gives these.
struct HeightCompensation {
  double heightScale;
  double heightBias;
};
HeightCompensation compensateLevels(const LevelsRange& range, double heightScale,
                                    double heightBias);

// The normal map's RGB with the height in A.
Image packHeightIntoNormalAlpha(const Image& normals, const Image& height);

// Builds an image from named inputs by a swizzle such as "n.r n.g n.b h.r" (one term per output
// channel: input letter, dot, channel r/g/b/a, or the constants 0 and 1). `names` are the input
// letters in the order of `inputs`; all inputs must have the same size.
Result<Image> swizzleChannels(const std::vector<const Image*>& inputs, const std::string& names,
                              const std::string& swizzle);

}  // namespace relief::core::inline generators
