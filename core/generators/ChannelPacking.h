// Channel packing: the height into the normal map's alpha (references 001 and 003: one RGBA
// texture, one fetch), any map channel or constant into any channel (the ORM and Unity mask-map
// layouts engines read among the named layouts), and auto-levels for heights with the applied
// range recorded so the material's height scale can compensate.
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"

#include <optional>
#include <string>
#include <string_view>
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

// One input of a channel pack: a map by the name terms use for it ("ao", "n").
struct NamedMap {
  std::string name;
  const Image* image = nullptr;
};

// Builds an image of 1 to 4 channels, one term per output channel: "NAME.c" (channel c, one of
// r g b a, of the input called NAME), "1-NAME.c" (its inverse, e.g. smoothness from roughness)
// or a constant in 0..1 ("0", "0.5", "1"). A grey input's g and b read its only channel and a
// missing alpha reads 1. All inputs must have the same size; the result is linear data.
Result<Image> packChannels(const std::vector<NamedMap>& inputs,
                           const std::vector<std::string>& terms);

// The same from one-letter input names and a space-separated swizzle ("n.r n.g n.b h.r");
// `names` holds the letters in the order of `inputs` (relief-cli generate pack --swizzle).
Result<Image> swizzleChannels(const std::vector<const Image*>& inputs, const std::string& names,
                              const std::string& swizzle);

// Channel layouts engines read, declared once for the CLI (generate pack --layout) and the
// engine exports. Terms name maps by their slot names ("ao", "roughness", "normal", "height",
// "color") or "metallic"; a map the material lacks is replaced by its neutral value (AO 1,
// roughness 1, metallic 0, height 0).
struct PackLayout {
  std::string_view name;  // relief-cli generate pack --layout <name>
  std::string_view label;
  std::string_view description;
  std::vector<std::string_view> terms;
};
const std::vector<PackLayout>& packLayouts();
const PackLayout* findPackLayout(std::string_view name);
// The reverse of a layout: the maps a packed texture holds, one single-channel image per term
// that names a map ("ao.r" -> ao; "1-roughness.a" -> roughness, inverted back), in the
// layout's order; constant terms are skipped. So an ORM texture (glTF, Unreal, Poly Haven's
// "arm") fills the AO, roughness and metallic slots. Refused when the image has fewer channels
// than the layout reads (a grey image is no ORM texture).
struct UnpackedMap {
  std::string name;  // the term's map name: a slot name or "normal", "height"
  Image image;
  int channel;  // the packed texture's channel it came from (0..3)
};
Result<std::vector<UnpackedMap>> unpackLayout(const Image& packed, const PackLayout& layout);

// The neutral value a missing map stands for, or nullopt for a name no layout uses.
std::optional<float> neutralMapValue(std::string_view name);

// The note that says a missing map's neutral value was used ("no roughness map: its neutral
// value 1 was used"), for the generator's notes and the CLI alike.
std::string neutralValueNote(std::string_view name);

// Resolves a layout's terms against the maps at hand: terms naming a missing map become its
// neutral value (the inverse for "1-" terms). `substituted` receives the names replaced.
std::vector<std::string> resolveLayoutTerms(const PackLayout& layout,
                                            const std::vector<NamedMap>& available,
                                            std::vector<std::string>* substituted = nullptr);

}  // namespace relief::core::inline generators
