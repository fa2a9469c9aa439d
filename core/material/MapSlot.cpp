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
  std::array<std::string_view, 6> hints;  // matched as whole words of the file stem
};

constexpr std::array<SlotInfo, kMapSlotCount> kSlots = {{
    {"color", "Colour", {"color", "colour", "albedo", "diffuse", "basecolor", "diff"}},
    {"normal", "Normal", {"normal", "nrm", "norm", "nor", "normalgl", "normaldx"}},
    {"height", "Height", {"height", "disp", "displacement", "bump", "depth", "parallax"}},
    {"ao", "Ambient occlusion", {"ao", "occlusion", "ambientocclusion", "", "", ""}},
    {"roughness", "Roughness", {"roughness", "rough", "rgh", "", "", ""}},
    {"metallic", "Metallic", {"metallic", "metalness", "metal", "mtl", "", ""}},
}};

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

ColorSpace mapSlotColorSpace(MapSlot slot) {
  return slot == MapSlot::Color ? ColorSpace::Srgb : ColorSpace::Linear;
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
  for (const std::string& word : stemWords(fileName)) {
    for (MapSlot slot : kAllMapSlots) {
      const auto& hints = kSlots[std::size_t(slot)].hints;
      if (std::find(hints.begin(), hints.end(), word) != hints.end())
        found = slot;
    }
  }
  return found;
}

bool isOrmFileName(std::string_view fileName) {
  const std::vector<std::string> words = stemWords(fileName);
  return std::any_of(words.begin(), words.end(),
                     [](const std::string& word) { return word == "orm" || word == "arm"; });
}

}  // namespace relief::core::inline material
