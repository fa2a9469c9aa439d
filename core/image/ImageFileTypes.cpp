// ImageFileTypes; see ImageFileTypes.h.
#include "core/image/ImageFileTypes.h"

#include <array>
#include <cctype>
#include <string>

namespace relief::core::inline image {
namespace {

constexpr std::array kTypes = {
    ImageFileType{"png", "PNG", 16, false},    ImageFileType{"jpg", "JPEG", 8, false},
    ImageFileType{"jpeg", "JPEG", 8, false},   ImageFileType{"tga", "TGA", 8, false},
    ImageFileType{"tif", "TIFF", 16, false},   ImageFileType{"tiff", "TIFF", 16, false},
    ImageFileType{"exr", "OpenEXR", 32, true},
};

}  // namespace

std::span<const ImageFileType> imageFileTypes() {
  return kTypes;
}

const ImageFileType* imageFileTypeForPath(std::string_view path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash))
    return nullptr;
  std::string extension(path.substr(dot + 1));
  for (char& c : extension)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const ImageFileType& type : kTypes) {
    if (type.extension == extension)
      return &type;
  }
  return nullptr;
}

}  // namespace relief::core::image
