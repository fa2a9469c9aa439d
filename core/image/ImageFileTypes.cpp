// ImageFileTypes; see ImageFileTypes.h.
#include "core/image/ImageFileTypes.h"

#include "core/base/Text.h"

#include <array>

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
  const std::string extension = lowerExtension(path);
  for (const ImageFileType& type : kTypes) {
    if (type.extension == extension)
      return &type;
  }
  return nullptr;
}

}  // namespace relief::core::image
