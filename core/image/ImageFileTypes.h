// The image file types Relief reads and writes (PNG itself, the rest through OpenImageIO), declared
// once: the map loaders' file filters and drop checks, the CLI's output checks and the sample
// format a save picks all read this table.
#pragma once

#include <span>
#include <string_view>

namespace relief::core::inline image {

struct ImageFileType {
  std::string_view extension;  // lower case, without the dot
  std::string_view label;
  int maxBitsPerChannel;  // 8, 16, or 32 (float)
  bool isFloat;
};

std::span<const ImageFileType> imageFileTypes();
// By the path's extension, case-insensitive; null when Relief does not handle the type.
const ImageFileType* imageFileTypeForPath(std::string_view path);

}  // namespace relief::core::image
