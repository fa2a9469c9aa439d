// A fast PNG writer for the maps Relief saves (8- or 16-bit, 1 to 4 channels). OpenImageIO's PNG
// writer (libpng with zlib level 6 and libpng's adaptive filters) took 9.5 s for a 4096x4096
// 16-bit RGB normal map, single-threaded, and reports success after a short write, so every
// save also decoded the file again. This one filters each row with Paeth, compresses strips of
// rows in parallel with zlib's run-length strategy (each strip its own IDAT chunk, joined as
// pigz joins deflate streams), checks every write, and takes 0.5 s for the same map on two
// threads, in 1.06x the bytes (tools/bench-cli).
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"

#include <string>

namespace relief::core::inline image {

struct PngWriteOptions {
  int bitsPerChannel = 8;  // 8 or 16
  // 8-bit only: add noise of under half a level before rounding, so that finer data (16-bit,
  // float) does not band; data that came from 8-bit files is written exactly without it.
  bool dither = false;
};

// Writes `image` to `path` (the file is created or truncated; the caller makes saves atomic).
// The colour space is recorded as PNG readers expect it: sRGB (sRGB, gAMA and cHRM chunks) or
// linear (gAMA 1.0), and as OpenImageIO's "oiio:ColorSpace" text, so Relief reads it back as it
// was. Fails with a message naming the file when a write fails (full disk, file-size limit).
Status writePng(const Image& image, const std::string& path, const PngWriteOptions& options);

}  // namespace relief::core::inline image
