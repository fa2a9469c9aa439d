#include "core/preset/OrmTexture.h"

#include "core/compression/MapFile.h"
#include "core/generators/ChannelPacking.h"

namespace relief::core::inline preset {

Result<std::vector<ChannelMap>> loadOrmTexture(const std::string& path) {
  Result<Image> image = loadMapFile(path);
  if (!image)
    return makeError(image.error());
  // The layout table says which channel holds which map, as for packing.
  const PackLayout& layout = *findPackLayout("orm");
  Result<std::vector<UnpackedMap>> unpacked = unpackLayout(image.value(), layout);
  if (!unpacked)
    return makeError(path + ": not an ORM texture: " + unpacked.error());
  std::vector<ChannelMap> maps;
  for (UnpackedMap& map : unpacked.value())
    maps.push_back({*findMapSlot(map.name), std::move(map.image), map.channel});
  return maps;
}

}  // namespace relief::core::inline preset
