// The map slots of a material and what each one holds: its preset key, its colour space and
// the file-name hints ("bricks_height.png") used to assign dropped files to slots.
#pragma once

#include "core/image/ColorSpace.h"

#include <array>
#include <optional>
#include <string_view>

namespace relief::core::inline material {

enum class MapSlot { Color, Normal, Height, AmbientOcclusion, Roughness, Metallic, Count };

constexpr std::size_t kMapSlotCount = std::size_t(MapSlot::Count);

constexpr std::array<MapSlot, kMapSlotCount> kAllMapSlots = {
    MapSlot::Color,     MapSlot::Normal,  MapSlot::Height, MapSlot::AmbientOcclusion,
    MapSlot::Roughness, MapSlot::Metallic};

// What a slot's texels are, which decides how they are stored on the GPU, which formats suit
// them and what an empty slot samples as: colour (sRGB), a tangent-space normal, or one channel
// of linear data (height, AO, roughness, metallic).
enum class MapTexels { Colour, Normal, Scalar };

std::string_view mapSlotName(MapSlot slot);   // "color", "normal", "height", "ao", "roughness",
                                              // "metallic"
std::string_view mapSlotLabel(MapSlot slot);  // "Colour", "Normal", ...
std::optional<MapSlot> findMapSlot(std::string_view name);

MapTexels mapSlotTexels(MapSlot slot);
// The sampler the shaders read the slot from ("uOcclusionMap"), and the bool that says whether
// the material has the map ("uHasOcclusionMap"; empty for a slot always sampled, whose empty
// map is the neutral texel). Both view string literals, so data() is a C string.
std::string_view mapSlotSampler(MapSlot slot);
std::string_view mapSlotPresenceFlag(MapSlot slot);
// The value an empty scalar slot samples as (height 1, AO 1, roughness 0, metallic 1).
float mapSlotNeutralValue(MapSlot slot);
// Colour maps are sRGB; everything else is linear data (DESIGN.md).
ColorSpace mapSlotColorSpace(MapSlot slot);

// Guesses the slot from a file name's hints (_height, _normal, _color, _albedo, _diffuse, ...),
// and from the short suffixes of game data as the name's last word (_n, _nm, _z, _h, _hm, _d,
// _cc), case-insensitively; nullopt when the name says nothing.
std::optional<MapSlot> guessMapSlotFromFileName(std::string_view fileName);
// True when the name ends in a specular or gloss suffix (_s, _spec, _sc, _gloss): a map Relief
// has no slot for.
bool isSpecularFileName(std::string_view fileName);
// True when the name says the file packs occlusion, roughness and metallic in R, G and B
// (_orm, or _arm as Poly Haven names them).
bool isOrmFileName(std::string_view fileName);

}  // namespace relief::core::inline material
