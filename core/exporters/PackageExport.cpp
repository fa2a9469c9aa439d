// PackageExport; see PackageExport.h.
#include "core/exporters/PackageExport.h"

#include "core/compression/CompressionJob.h"
#include "core/compression/TextureFile.h"
#include "core/image/ImageIO.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace relief::core::inline exporters {

Status makeExportFolder(const std::string& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec)
    return makeError(folder + ": cannot create the folder (" + ec.message() + ")");
  return {};
}

std::string exportStem(const Material& material) {
  std::string stem = material.name().empty() ? std::string("material") : material.name();
  // File systems allow 255 bytes a name, and a name runs through every error message: a few
  // words are enough (a 50 MB name once filled a terminal).
  constexpr std::size_t kMaxStem = 80;
  if (stem.size() > kMaxStem)
    stem.resize(kMaxStem);
  std::replace_if(
      stem.begin(), stem.end(),
      [](unsigned char c) { return !(std::isalnum(c) || c == '-' || c == '_'); }, '_');
  return stem;
}

namespace {

// The compressed copy of one map, when the preset has a compression choice for it.
Status writeCompressed(const Preset& preset, MapSlot slot, const std::string& folder,
                       const std::string& stem, const PackageOptions& options,
                       const WorkControl& control) {
  const MapCompression& choice = preset.compression[std::size_t(slot)];
  if (options.textures == PackageTextures::None || !choice)
    return {};
  CompressionJob job;
  job.map = preset.material.map(slot).image;
  job.slot = slot;
  job.settings = *choice;
  job.measure = false;
  job.spreadNormals = preset.material.map(MapSlot::Normal).image;
  Result<CompressionOutcome> outcome = runCompressionJob(job, control);
  if (!outcome) {
    const std::string& source = preset.material.map(slot).sourcePath;
    return makeError((source.empty() ? std::string(mapSlotLabel(slot)) + " map" : source) + ": " +
                     outcome.error());
  }
  const TextureContainer container =
      containerFor(choice->format, options.textures == PackageTextures::DdsWherePossible);
  const std::string path =
      (std::filesystem::path(folder) /
       (stem + "_" + std::string(mapSlotName(slot)) + std::string(containerExtension(container))))
          .string();
  return saveCompressedTexture(*outcome->texture, path,
                               container == TextureContainer::Ktx2 ? choice->zstdLevel : 0);
}

}  // namespace

Result<std::string> exportPackage(const Preset& preset, const std::string& folder,
                                  const PackageOptions& options, const WorkControl& control) {
  if (Status made = makeExportFolder(folder); !made)
    return makeError(made.error());
  const std::string stem = exportStem(preset.material);
  Preset packaged = preset;
  for (MapSlot slot : kAllMapSlots) {
    const MaterialMap& map = preset.material.map(slot);
    if (!map.image)
      continue;
    if (control.cancelled())
      return makeError("cancelled");
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
    if (Status compressed = writeCompressed(preset, slot, folder, stem, options, control);
        !compressed)
      return makeError(control.cancelled() ? "cancelled" : compressed.error());
  }
  // A mesh file travels with the package; primitives are names.
  if (std::filesystem::path(packaged.view.mesh).has_extension()) {
    const std::filesystem::path source(packaged.view.mesh);
    const std::filesystem::path copy = std::filesystem::path(folder) / source.filename();
    std::error_code ec;
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

}  // namespace relief::core::inline exporters
