// Checks a PNG's chunk lengths before libpng reads the file. libpng allocates a text chunk's
// declared length before reading it: a 318-byte file whose tEXt chunk claims 1.9 GB made
// `relief-cli info` take 2.1 GB (found by tests/fuzz). Every chunk must lie inside the file and
// within the PNG specification's limit of 2^31-1 bytes (PNG 1.2, section 3.2 "Chunk layout").
#pragma once

#include "core/base/Result.h"

#include <cstdint>
#include <string>

namespace relief::core::inline image {

// The problem with the chunk layout, naming the file and the chunk; ok when every chunk fits.
Status preflightPng(const std::string& path, std::uintmax_t fileBytes);

}  // namespace relief::core::inline image
