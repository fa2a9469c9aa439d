// PackageExport; see PackageExport.h.
#include "core/export/PackageExport.h"

#include "core/ImageIO.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace relief::core {

std::string exportStem(const Material& material) {
  std::string stem = material.name().empty() ? std::string("material") : material.name();
  std::replace_if(
      stem.begin(), stem.end(),
      [](unsigned char c) { return !(std::isalnum(c) || c == '-' || c == '_'); }, '_');
  return stem;
}

Result<std::string> exportPackage(const Preset& preset, const std::string& folder,
                                  const PackageOptions& options) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec)
    return makeError(folder + ": cannot create the folder (" + ec.message() + ")");
  const std::string stem = exportStem(preset.material);
  Preset packaged = preset;
  for (MapSlot slot : kAllMapSlots) {
    const MaterialMap& map = preset.material.map(slot);
    if (!map.image)
      continue;
    std::string extension = ".png";
    SampleFormat format = SampleFormat::UInt8;
    if (slot != MapSlot::Color) {
      switch (options.dataMaps) {
        case PackageMapFormat::Png8:
          break;
        case PackageMapFormat::Png16:
          format = SampleFormat::UInt16;
          break;
        case PackageMapFormat::Exr:
          extension = ".exr";
          format = SampleFormat::Float;
          break;
      }
    }
    const std::string path =
        (std::filesystem::path(folder) / (stem + "_" + std::string(mapSlotName(slot)) + extension))
            .string();
    if (Status saved = saveImage(*map.image, path, format); !saved) {
      return makeError(saved.error());
    }
    packaged.material.setMap(slot, map.image, std::filesystem::absolute(path).string());
  }
  // A mesh file travels with the package; primitives are names.
  if (std::filesystem::path(packaged.view.mesh).has_extension()) {
    const std::filesystem::path source(packaged.view.mesh);
    const std::filesystem::path copy = std::filesystem::path(folder) / source.filename();
    std::filesystem::copy_file(source, copy, std::filesystem::copy_options::overwrite_existing, ec);
    if (ec)
      return makeError(source.string() + ": cannot copy the mesh (" + ec.message() + ")");
    packaged.view.mesh = std::filesystem::absolute(copy).string();
  }
  const std::string presetPath = (std::filesystem::path(folder) / (stem + ".relief")).string();
  if (auto saved = savePreset(packaged, presetPath); !saved)
    return makeError(saved.error());
  return presetPath;
}

}  // namespace relief::core
