// Proves a PNG's pixel data intact without holding its pixels: every chunk's CRC, the zlib
// stream and its Adler-32, each row's filter type, the stream's length against the header
// (Adam7 passes included) and every palette index against the palette. Streams the file in
// pieces (zlib's inflate), so `relief-cli info` of an 8192x8192 map needs a few rows of memory.
// The checks are PngReader's (a file this accepts, PngReader decodes); without OpenImageIO.
#pragma once

#include "core/base/Result.h"
#include "core/image/PngPreflight.h"

#include <string>

namespace relief::core::inline image {

// `header` is preflightPng's reading of the same file.
Status verifyPngData(const std::string& path, const PngHeader& header);

}  // namespace relief::core::inline image
