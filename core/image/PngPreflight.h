// Checks a PNG's chunks before libpng reads the file. libpng allocates a text chunk's declared
// length before reading it: a 318-byte file whose tEXt chunk claims 1.9 GB made `relief-cli info`
// take 2.1 GB (found by tests/fuzz). Every chunk must lie inside the file and within the PNG
// specification's limit of 2^31-1 bytes (PNG 1.2, section 3.2 "Chunk layout"), and the IDAT
// chunks must be able to hold the pixels the header claims, counted as the file stores them.
#pragma once

#include "core/base/Result.h"

#include <cstdint>
#include <string>

namespace relief::core::inline image {

// The problem with the chunk layout, naming the file and the chunk; ok when every chunk fits.
Status preflightPng(const std::string& path, std::uintmax_t fileBytes);

// The fewest bytes the inflated pixel stream of a PNG with this header can have: each row's
// filter byte and its samples at the stored bit depth (a palette image stores one index of 1 to 8
// bits per pixel, not the RGB it expands to). Adam7 interlacing only adds filter bytes, so the
// non-interlaced count is the lower bound for both.
std::uint64_t pngMinimumInflatedBytes(std::uint32_t width, std::uint32_t height, int bitDepth,
                                      int colourType);

}  // namespace relief::core::inline image
