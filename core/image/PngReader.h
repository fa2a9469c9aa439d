// A fast decoder for the pixels of the PNGs Relief reads most: height and normal maps of 8 or 16
// bits, grey, grey with alpha, RGB or RGBA, and palette and 1, 2 or 4-bit grey images (game
// height maps are often saved with a palette), not interlaced. OpenImageIO's PNG reader (libpng,
// zlib's streaming inflate, a conversion per scanline) took 350 ms of the 1.4 s that
// `relief-cli generate normal` spent on a 4096x4096 16-bit map; this one inflates the whole
// image at once with libdeflate (2.5x zlib's speed), into the float image's own buffer so that
// no second copy of the pixels is held, and takes about 150 ms (tools/bench-cli).
// It also refuses a palette index past the palette's end, which libpng silently reads as black.
// Interlaced files and the colour-key transparency of grey and RGB images are left to
// OpenImageIO (its module, OiioModule.h); the header and colour space are PngPreflight's.
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"

#include <string>

namespace relief::core::inline image {

enum class PngFastDecode {
  Decoded,     // `image` holds the pixels
  NotHandled,  // the file uses a feature left to OpenImageIO; `image` is untouched
};

// Decodes the pixels of the PNG at `path` into `image`, which the caller has sized from the
// header (width, height, channels). Values are scaled to [0, 1] as OpenImageIO scales them
// (v times 1/255 or 1/65535, in float, bit for bit). Fails with a message naming the file on
// damaged data: a chunk's CRC, the zlib stream, its Adler-32, an unknown row filter, a palette
// index past the palette or a palette image without one.
Result<PngFastDecode> decodePngPixels(const std::string& path, Image& image);

}  // namespace relief::core::inline image
