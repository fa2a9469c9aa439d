// What Relief asks of OpenImageIO, as an interface of plain types: the module librelief_oiio.so
// implements it (OiioPlugin.cpp, the only code that includes OpenImageIO) and is loaded the
// first time a file needs it (core/base/ModuleLoader.h): JPEG, TGA, TIFF, EXR and HDR files, and
// the PNG features Relief's own reader leaves (interlacing, a grey or RGB colour key). Both sides
// are built from this header by the same compiler, so the classes may carry std types.
#pragma once

#include "core/base/Result.h"

#include <memory>
#include <string>

namespace relief::core::inline image {

// What OpenImageIO reports of a file's first subimage.
struct OiioHeader {
  int width = 0, height = 0, depth = 0;
  int channels = 0;
  int bitsPerSample = 0;  // "oiio:BitsPerSample", else the sample type's size
  bool isFloat = false;
  std::string formatName;      // "png", "openexr", "jpeg", ...
  std::string colorSpaceName;  // "oiio:ColorSpace"
  int subimages = 1;           // an EXR's parts, a TIFF's pages; Relief reads the first
  std::string subimageName;    // the first part's name ("oiio:subimagename"), if it has one
};

class OiioInput {
 public:
  virtual ~OiioInput() = default;
  virtual const OiioHeader& header() const = 0;
  // The first `channels` channels of every pixel, as float; then closes the file (a damaged
  // last chunk is reported on closing).
  virtual Status readImage(int channels, float* pixels) = 0;
  // Decodes every pixel a strip of rows at a time (memory stays small) to prove the file intact.
  virtual Status verify() = 0;
};

enum class OiioSampleType { UInt8, UInt16, Half, Float };

struct OiioWriteRequest {
  const float* pixels = nullptr;
  int width = 0, height = 0, channels = 0;
  OiioSampleType sampleType = OiioSampleType::UInt8;
  bool srgb = false;    // tagged sRGB, else linear
  bool zip = false;     // zip compression (EXR)
  bool dither = false;  // dither when quantising to 8 bits
};

class OiioModule {
 public:
  virtual ~OiioModule() = default;
  // Opens `path` with the reader named `readerName` (an OpenImageIO format name or extension)
  // only: OpenImageIO's own open() tries every reader it has when the first fails. Errors name
  // the file.
  virtual Result<std::unique_ptr<OiioInput>> open(const std::string& path,
                                                  const std::string& readerName) = 0;
  // Writes an image to `temporary` in the file type of `path`'s extension (the caller decodes it
  // back before it replaces `path`: some writers report success after a short write). Errors
  // name `path`.
  virtual Status write(const std::string& path, const std::string& temporary,
                       const OiioWriteRequest& request) = 0;
};

// The module, loaded on the first call; an error says why it cannot be loaded and names `needs`.
Result<OiioModule*> oiioModule(const std::string& needs);

}  // namespace relief::core::inline image

// The module's entry point.
extern "C" relief::core::OiioModule* reliefOiioModule();
