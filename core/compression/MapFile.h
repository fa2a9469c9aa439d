// A map from any file Relief reads: an image (through OpenImageIO) or a compressed texture
// (DDS, KTX2), decoded as the map it holds. Relief's own DDS and KTX2 readers decide for those
// formats: OpenImageIO is never handed one (its DDS reader spins forever on uncompressed DDS and
// accepts truncated files). Presets, the CLI and the editor load maps through here.
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"

#include <string>

namespace relief::core::inline compression {

// The top mip level; normal maps from two-channel formats get Z rebuilt. Errors name the file.
Result<Image> loadMapFile(const std::string& path);

}  // namespace relief::core::compression
