// Fuzz target for `.relief` presets (core/preset/MaterialPreset): JSON parsing, migration,
// every parameter, map entry, compression choice and view field. Map paths in the inputs are
// resolved next to the input file, where nothing else exists.
#include "FuzzInput.h"

#include "core/preset/MaterialPreset.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = relief::fuzz::writeFuzzInput(data, size, "relief");
  (void)relief::core::loadPreset(path);
  return 0;
}
