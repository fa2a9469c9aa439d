// MapFile; see MapFile.h.
#include "core/compression/MapFile.h"

#include "core/compression/TextureFile.h"
#include "core/image/ImageIO.h"

namespace relief::core::inline compression {

Result<Image> loadMapFile(const std::string& path) {
  if (!containerForPath(path))
    return loadImage(path);
  Result<CompressedTexture> texture = loadCompressedTexture(path);
  if (!texture)
    return makeError(texture.error());
  Result<Image> map = decodeAsMap(texture.value());
  if (!map)
    return makeError(path + ": " + map.error());
  return map;
}

}  // namespace relief::core::compression
