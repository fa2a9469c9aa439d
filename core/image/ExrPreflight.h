// Checks an OpenEXR file's header before OpenEXR reads it. OpenEXR 3.1 allocates what a header
// claims before it knows the file holds it: an attribute whose size field says 1.9 GB is read
// into a string of that size, and a 16384x16384 data window in 1x1 tiles gets a 2 GiB tile
// offset table, from files of a few hundred bytes (both found by tests/fuzz). Here every
// attribute must lie inside the file, and the chunk offset table the header implies must fit
// in it. Layout from the OpenEXR file format document ("OpenEXR File Layout").
#pragma once

#include "core/base/Result.h"

#include <cstdint>
#include <string>

namespace relief::core::inline image {

// The problem with the header, naming the file and the field; ok for files whose header holds.
Status preflightExr(const std::string& path, std::uintmax_t fileBytes);

}  // namespace relief::core::inline image
