// Map slot names and file-name hints; see MapSlot.h.
#include "core/material/MapSlot.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace relief::core::inline material {
namespace {

struct SlotInfo {
  std::string_view name;
  std::string_view label;
  MapTexels texels;
  // The shaders' sampler2D and, for a slot they sample only when the material has its map, the
  // bool saying so; empty when there is none. The renderer declares both in the shaders from
  // here (renderer/ShaderVariant.cpp) and binds them. Literals: it passes them to GL as C
  // strings.
  std::string_view sampler;
  std::string_view presence;
  // What an empty scalar slot means: the top surface, no occlusion, no roughness (the parameter
  // alone applies), a metallic texel of 1 (pbr multiplies the metallic factor by it).
  float neutral;
  std::array<std::string_view, 6> hints;  // matched as whole words of the file stem
  // Short suffixes game data uses ("wall_n.png", "floor_hm.jpg": Cube 2 and Red Eclipse name
  // their texture slots 0/d, n, z, s), matched only as the stem's last word: "n" or "d" in the
  // middle of a name says nothing.
  std::array<std::string_view, 4> suffixes;
};

constexpr std::array<SlotInfo, kMapSlotCount> kSlots = {{
    {"color",
     "Colour",
     MapTexels::Colour,
     "uColorMap",
     "",
     0.0f,
     {"color", "colour", "albedo", "diffuse", "basecolor", "diff"},
     {"d", "cc", "col", "c"}},
    {"normal",
     "Normal",
     MapTexels::Normal,
     "uNormalMap",
     "",
     0.0f,
     {"normal", "nrm", "norm", "nor", "normalgl", "normaldx"},
     {"n", "nm", "nml", ""}},
    {"height",
     "Height",
     MapTexels::Scalar,
     "uHeightMap",
     "",
     1.0f,
     {"height", "disp", "displacement", "bump", "depth", "parallax"},
     {"z", "h", "hm", "heightmap"}},
    {"ao",
     "Ambient occlusion",
     MapTexels::Scalar,
     "uOcclusionMap",
     "uHasOcclusionMap",
     1.0f,
     {"ao", "occlusion", "ambientocclusion", "", "", ""},
     {"occ", "", "", ""}},
    {"roughness",
     "Roughness",
     MapTexels::Scalar,
     "uRoughnessMap",
     "uHasRoughnessMap",
     0.0f,
     {"roughness", "rough", "rgh", "", "", ""},
     {"", "", "", ""}},
    {"metallic",
     "Metallic",
     MapTexels::Scalar,
     "uMetallicMap",
     "uHasMetallicMap",
     1.0f,
     {"metallic", "metalness", "metal", "mtl", "", ""},
     {"", "", "", ""}},
}};

// Specular and gloss maps: Relief's materials have no slot for them (roughness is the
// metallic-roughness counterpart of gloss, inverted), so they are recognised, never guessed
// into another slot.
constexpr std::array<std::string_view, 6> kSpecularWords = {"spec",  "specular",   "sc",
                                                            "gloss", "glossiness", "s"};

std::string lowerStem(std::string_view fileName) {
  std::string name(fileName);
  const std::size_t slash = name.find_last_of("/\\");
  if (slash != std::string::npos)
    name.erase(0, slash + 1);
  const std::size_t dot = name.find_last_of('.');
  if (dot != std::string::npos && dot > 0)
    name.erase(dot);
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return name;
}

}  // namespace

std::string_view mapSlotName(MapSlot slot) {
  return kSlots[std::size_t(slot)].name;
}
std::string_view mapSlotLabel(MapSlot slot) {
  return kSlots[std::size_t(slot)].label;
}

std::optional<MapSlot> findMapSlot(std::string_view name) {
  for (MapSlot slot : kAllMapSlots) {
    if (mapSlotName(slot) == name)
      return slot;
  }
  return std::nullopt;
}

MapTexels mapSlotTexels(MapSlot slot) {
  return kSlots[std::size_t(slot)].texels;
}

std::string_view mapSlotSampler(MapSlot slot) {
  return kSlots[std::size_t(slot)].sampler;
}

std::string_view mapSlotPresenceFlag(MapSlot slot) {
  return kSlots[std::size_t(slot)].presence;
}

float mapSlotNeutralValue(MapSlot slot) {
  return kSlots[std::size_t(slot)].neutral;
}

ColorSpace mapSlotColorSpace(MapSlot slot) {
  return mapSlotTexels(slot) == MapTexels::Colour ? ColorSpace::Srgb : ColorSpace::Linear;
}

namespace {

// The stem's words, split at separators, so "rock_nor_gl" has "nor" but "minor" does not.
std::vector<std::string> stemWords(std::string_view fileName) {
  const std::string stem = lowerStem(fileName);
  std::vector<std::string> words;
  std::size_t start = 0;
  while (start <= stem.size()) {
    std::size_t end = stem.find_first_of("_-. ", start);
    if (end == std::string::npos)
      end = stem.size();
    if (end > start)
      words.push_back(stem.substr(start, end - start));
    start = end + 1;
  }
  return words;
}

}  // namespace

std::optional<MapSlot> guessMapSlotFromFileName(std::string_view fileName) {
  // The last matching word wins: "brick_normal_height" is a height map of bricks.
  std::optional<MapSlot> found;
  const std::vector<std::string> words = stemWords(fileName);
  for (std::size_t i = 0; i < words.size(); ++i) {
    const bool last = i + 1 == words.size() && words.size() > 1;
    for (MapSlot slot : kAllMapSlots) {
      const SlotInfo& info = kSlots[std::size_t(slot)];
      const bool hint =
          std::find(info.hints.begin(), info.hints.end(), words[i]) != info.hints.end();
      const bool suffix =
          last && !words[i].empty() &&
          std::find(info.suffixes.begin(), info.suffixes.end(), words[i]) != info.suffixes.end();
      if (hint || suffix)
        found = slot;
    }
  }
  return found;
}

bool isSpecularFileName(std::string_view fileName) {
  const std::vector<std::string> words = stemWords(fileName);
  if (words.size() < 2)
    return false;
  // A hint of a slot later in the name wins ("spec_normal" is a normal map).
  return std::find(kSpecularWords.begin(), kSpecularWords.end(), words.back()) !=
             kSpecularWords.end() &&
         !guessMapSlotFromFileName(fileName);
}

bool isOrmFileName(std::string_view fileName) {
  const std::vector<std::string> words = stemWords(fileName);
  return std::any_of(words.begin(), words.end(),
                     [](const std::string& word) { return word == "orm" || word == "arm"; });
}

}  // namespace relief::core::inline material
