// Export as a package: a folder with the material's maps in the chosen file formats and a
// preset that points at them, ready to copy into another project or hand to a colleague.
#pragma once

#include "core/base/Result.h"
#include "core/base/WorkControl.h"
#include "core/preset/MaterialPreset.h"

#include <string>

namespace relief::core::inline exporters {

enum class PackageMapFormat {
  Png8,   // 8-bit PNG (data maps dithered)
  Png16,  // 16-bit PNG (the colour map stays 8-bit sRGB)
  Exr,    // float EXR (the colour map stays 8-bit sRGB PNG)
};

// Maps the preset says to compress (its `compression` choices) are also written compressed:
// as KTX2, or as DDS for the BC formats (KTX2 for the rest, which DDS readers do not know).
enum class PackageTextures { None, Ktx2, DdsWherePossible };

struct PackageOptions {
  PackageMapFormat dataMaps = PackageMapFormat::Png16;  // normal, height, AO, roughness
  PackageTextures textures = PackageTextures::Ktx2;
};

// Writes <folder>/<name>_<slot>.<ext> and <folder>/<name>.relief (creating the folder), plus
// <name>_<slot>.ktx2 or .dds for each map with a compression choice (the preset keeps pointing
// at the lossless files). Returns the preset's path; fails with "cancelled" when cancelled
// (checked between maps and inside compression).
Result<std::string> exportPackage(const Preset& preset, const std::string& folder,
                                  const PackageOptions& options = {},
                                  const WorkControl& control = {});

// Creates the export folder (and its parents); fails with a message naming it.
Status makeExportFolder(const std::string& folder);

// The file name stem exports use: the material's name, or "material", made safe for files.
std::string exportStem(const Material& material);

}  // namespace relief::core::inline exporters
