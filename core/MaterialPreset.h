// Reading and writing `.relief` presets: UTF-8 JSON with a format name, an integer version,
// map paths relative to the preset, the technique and every parameter by its declared name.
#pragma once

#include "core/Material.h"
#include "core/Result.h"

#include <string>
#include <vector>

namespace relief::core {

constexpr std::string_view kPresetFormatName = "relief-material";
constexpr int kPresetVersion = 1;

struct LoadedPreset {
  Material material;
  // Problems that did not stop the load: a missing map, a value out of range (clamped), an
  // unknown parameter. Each names the preset file.
  std::vector<std::string> warnings;
};

// Loads the preset and the maps it names. Fails (naming the file) on unreadable or malformed
// JSON, a wrong format name, or a version newer than this program understands.
Result<LoadedPreset> loadPreset(const std::string& path);

// Writes the preset atomically; map paths are stored relative to the preset's folder.
Status savePreset(const Material& material, const std::string& path);

}  // namespace relief::core
