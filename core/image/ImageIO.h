// Loading and saving Images: PNG (1-16 bit; Relief's own reader and writer), JPEG, TGA, TIFF
// and OpenEXR (half/float) through OpenImageIO, loaded when a file first needs it. Sizes are
// validated from the header before any pixel memory is allocated, and saves are atomic: a failed
// save leaves an existing file untouched.
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"

#include <cstdint>
#include <string>

namespace relief::core::inline image {

// The largest image file read: a 16384x16384 RGBA float EXR without compression is 4 GiB.
constexpr std::uintmax_t kMaxImageFileBytes = std::uintmax_t(5) << 30;
// EXRs may carry many layers; Relief uses the first four channels and refuses absurd counts
// (a damaged header's 1000 channels would make every row buffer a thousand times larger).
constexpr int kMaxImageChannels = 64;

// What a file's header says, without reading its pixels.
struct ImageFileInfo {
  int width = 0;
  int height = 0;
  int channels = 0;
  int bitsPerChannel = 0;
  bool isFloat = false;
  std::string formatName;  // OpenImageIO's names: "png", "openexr", "jpeg", ...
  ColorSpace colorSpace = ColorSpace::Linear;
  int subimages = 1;         // a multi-part EXR's parts, a multi-page TIFF's pages
  std::string subimageName;  // the name of the first, which Relief reads (EXR parts have one)
};

enum class SampleFormat {
  Auto,  // the image's source bit depth where the format supports it, else the format's best
  UInt8,
  UInt16,
  Half,
  Float,
};

Result<ImageFileInfo> readImageInfo(const std::string& path);

// The finest sample format the file type holds, for maps that must not lose precision: float
// for EXR, 16-bit for PNG and TIFF, 8-bit (dithered by saveImage) for the rest.
SampleFormat fullPrecisionFormatFor(const std::string& path);

// Decodes every pixel (a strip of rows at a time, so memory stays small) to prove the file is
// intact: catches truncation and checksum errors that the header alone does not show.
Status verifyImageData(const std::string& path);

// Reads the first subimage as float. Images with more than four channels keep the first four.
Result<Image> loadImage(const std::string& path);

// Writes to a temporary file next to `path` and renames it over `path` on success. Writing
// 8-bit samples from a finer source (not loaded from an 8-bit file) dithers.
Status saveImage(const Image& image, const std::string& path,
                 SampleFormat format = SampleFormat::Auto);

}  // namespace relief::core::inline image
