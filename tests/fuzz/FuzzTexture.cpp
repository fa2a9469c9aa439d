// Fuzz target for Relief's DDS and KTX2 readers (core/compression/TextureFile, MapFile): the
// whole path a map takes, from the file's header checks to the decoded top level.
// RELIEF_FUZZ_EXTENSION is "dds" or "ktx2" (tests/fuzz/CMakeLists.txt builds one of each).
#include "FuzzInput.h"

#include "core/compression/MapFile.h"
#include "core/compression/TextureFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = relief::fuzz::writeFuzzInput(data, size, RELIEF_FUZZ_EXTENSION);
  // Every level, as `relief-cli info` and `decode` read them, then the map as presets load it.
  (void)relief::core::loadCompressedTexture(path);
  (void)relief::core::loadMapFile(path);
  return 0;
}
