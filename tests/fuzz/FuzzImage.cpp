// Fuzz target for the image reader (core/image/ImageIO over OpenImageIO): the header checks,
// the streamed verification `relief-cli info` runs, and a full load. RELIEF_FUZZ_EXTENSION is
// "png", "tif" or "exr"; the extension only chooses OpenImageIO's first guess, the file's
// bytes decide.
#include "FuzzInput.h"

#include "core/image/ImageIO.h"

#include <algorithm>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = relief::fuzz::writeFuzzInput(data, size, RELIEF_FUZZ_EXTENSION);
  const relief::core::Result<relief::core::ImageFileInfo> info = relief::core::readImageInfo(path);
  if (!info)
    return 0;
  (void)relief::core::verifyImageData(path);
  // Headers may legally claim up to 16384x16384 (4 GiB of floats for RGBA); such inputs are
  // the 8192x8192 memory test's business, not the fuzzer's, whose memory limit is 2 GiB.
  if (double(info.value().width) * info.value().height * std::min(info.value().channels, 4) <=
      double(1 << 24)) {
    (void)relief::core::loadImage(path);
  }
  return 0;
}
