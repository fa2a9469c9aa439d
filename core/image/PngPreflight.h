// Reads a PNG's header and checks its chunks before any pixel is decoded, without OpenImageIO.
// - What the header says: size, bit depth, colour type, interlacing, and what a reader delivers
//   from them (channels after palette expansion and transparency, 8 or 16 bits) and the colour
//   space, by the same rules as OpenImageIO 2.4's PNG reader, so a map reads the same whichever
//   reader decodes its pixels: an sRGB chunk means sRGB; else a gAMA chunk whose decoding gamma
//   rounds to 1.00 means linear and any other gamma a gamma curve (sRGB for Relief); no chunk
//   means sRGB; a text chunk "oiio:ColorSpace" (Relief's and OpenImageIO's PNG writers add one)
//   overrides them. Like libpng, an ancillary chunk with a bad CRC or out of place is ignored.
// - That the chunks hold together: libpng allocates a text chunk's declared length before
//   reading it (a 318-byte file whose tEXt chunk claims 1.9 GB made `relief-cli info` take
//   2.1 GB; found by tests/fuzz). Every chunk must lie inside the file and within the
//   specification's limit of 2^31-1 bytes (section 5.3), and the IDAT chunks must be able to hold
//   the pixels the header claims, counted as the file stores them.
#pragma once

#include "core/base/Result.h"
#include "core/image/ColorSpace.h"

#include <cstdint>
#include <string>

namespace relief::core::inline image {

struct PngHeader {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  int bitDepth = 0;                // as stored: 1, 2, 4, 8 or 16
  int colourType = 0;              // 0 grey, 2 RGB, 3 palette, 4 grey and alpha, 6 RGBA
  int interlace = 0;               // 0 none, 1 Adam7
  bool transparencyChunk = false;  // a valid tRNS: palette alphas or a colour key
  ColorSpace colorSpace = ColorSpace::Srgb;

  // Channels as decoded: a palette expands to RGB, and tRNS adds an alpha channel.
  int channels() const;
  // Bits per decoded channel: 16 for 16-bit files, 8 for the rest (lower depths expand).
  int bitsPerChannel() const { return bitDepth == 16 ? 16 : 8; }
};

// The header of the PNG at `path` (`fileBytes` long), or what is wrong with its chunks, naming
// the file and the chunk. Fails for files without PNG's signature.
Result<PngHeader> preflightPng(const std::string& path, std::uintmax_t fileBytes);

// The fewest bytes the inflated pixel stream of a PNG with this header can have: each row's
// filter byte and its samples at the stored bit depth (a palette image stores one index of 1 to 8
// bits per pixel, not the RGB it expands to). Adam7 interlacing only adds filter bytes, so the
// non-interlaced count is the lower bound for both.
std::uint64_t pngMinimumInflatedBytes(std::uint32_t width, std::uint32_t height, int bitDepth,
                                      int colourType);

}  // namespace relief::core::inline image
