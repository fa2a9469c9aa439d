// Shared by the fuzz targets: every Relief reader takes a path (the input policy starts with
// the file itself: regular file, size cap), so each input is written to a file first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace relief::fuzz {

// Writes the bytes to one file per process in a private temporary folder (under /dev/shm when
// it exists, so fuzzing does not wear a disk) and returns its path, ending in `.extension`.
std::string writeFuzzInput(const std::uint8_t* data, std::size_t size, std::string_view extension);

}  // namespace relief::fuzz
