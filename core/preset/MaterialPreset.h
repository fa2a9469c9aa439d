// `.relief` presets: UTF-8 JSON with a format name and an integer version, the technique, every
// parameter by its declared name, the maps (paths relative to the preset, colour space,
// compression choice) and optionally the view (camera, light, mesh). The format is documented
// in docs/preset-format.md. Keys this program does not know are kept and written back.
#pragma once

#include "core/base/Result.h"
#include "core/compression/TextureFormat.h"
#include "core/material/Material.h"
#include "core/view/ViewState.h"

#include <QJsonObject>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace relief::core::inline preset {

constexpr std::string_view kPresetFormatName = "relief-material";
// 1: the first format (technique, parameters, maps). 2: adds per-map compression choices and
// the optional view (camera, light, mesh). 3: pbr becomes the default shading and the view
// gains its environment; older files are migrated on load (migrate() in the .cpp) and written
// back as 3.
constexpr int kPresetVersion = 3;
// Presets are small JSON files (a few KiB); anything larger is refused before it is read.
constexpr qint64 kMaxPresetBytes = qint64(16) << 20;

// How a map should be compressed when exported; empty = not compressed. In a file it is
// {"format": "bc5", "quality": "normal", "mipmaps": true}, names from the format table
// (TextureFormat.h); an unknown format is reported and dropped.
using MapCompression = std::optional<CompressionSettings>;

struct Preset {
  Material material;
  ViewState view;
  std::array<MapCompression, kMapSlotCount> compression;
  // The JSON as it was read (after migration), so keys this program does not know survive a
  // load-and-save; empty for a new preset.
  QJsonObject preserved;
};

struct LoadedPreset {
  Preset preset;
  // Problems that did not stop the load: a missing map, a value out of range (clamped), a
  // wrong type (default kept), an unknown parameter. Each names the preset file.
  std::vector<std::string> warnings;
  int fileVersion = kPresetVersion;  // the version the file had before migration
};

// A parameter's value as the preset writes it: a Bool as true/false, a Choice by its name, a
// number as it is. The glTF export's extras.relief use the same spelling.
QJsonValue parameterJson(const ParameterSpec& spec, double value);

// Loads the preset and the maps it names. Fails (naming the file) on unreadable or malformed
// JSON, a wrong format name, or a version newer than this program understands.
Result<LoadedPreset> loadPreset(const std::string& path);

struct SavedPreset {
  // Maps that had no file (generated in the editor) and were written next to the preset; the
  // material should take these paths so the next save does not write them again.
  std::vector<std::pair<MapSlot, std::string>> writtenMaps;
};

// Writes the preset atomically (AtomicFile: a failed save leaves the old file as it was). Map
// paths are stored relative to the preset's folder; maps without a file are written first as
// <preset name>_<slot>.png (16-bit; colour 8-bit sRGB) or .exr when they hold values outside
// 0..1.
Result<SavedPreset> savePreset(const Preset& preset, const std::string& path);

}  // namespace relief::core::inline preset
