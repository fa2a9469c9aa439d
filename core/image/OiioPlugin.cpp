// The OpenImageIO module (librelief_oiio.so): OiioModule.h implemented with OpenImageIO 2.4.
// Built as a shared object of its own and loaded on demand (core/base/ModuleLoader.h); it uses
// only header-only parts of core (Result, ThirdPartyAllocationScope), never core's compiled code.
#include "core/base/ThirdPartyAllocationScope.h"
#include "core/image/OiioModule.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <fstream>
#include <vector>

namespace relief::core::inline image {
namespace {

// OpenImageIO's messages often repeat the path and end with newlines; keep them readable.
std::string cleanOiioMessage(std::string message) {
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) {
    message.pop_back();
  }
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message.empty() ? std::string("unknown error") : message;
}

// OpenImageIO 2.4 sets a TGA's "oiio:BitsPerSample" to the stored bits per pixel over the
// channels, which for a colour-mapped file divides the 8-bit index (8 / 3 = 2 bits). Its texels
// have the palette entries' depth: 8 bits a channel for 24- and 32-bit entries, 5 for 15- and
// 16-bit ones (TGA header: image type at byte 2, 1 or 9 when colour-mapped; entry size at 7).
int targaBitsPerSample(const std::string& path, int reported) {
  unsigned char header[8] = {};
  std::ifstream file(path, std::ios::binary);
  if (!file.read(reinterpret_cast<char*>(header), sizeof header))
    return reported;
  const bool colourMapped = header[2] == 1 || header[2] == 9;
  if (!colourMapped)
    return reported;
  return header[7] >= 24 ? 8 : 5;
}

class Input final : public OiioInput {
 public:
  Input(std::string path, std::unique_ptr<OIIO::ImageInput> input)
      : m_path(std::move(path)), m_input(std::move(input)) {
    const OIIO::ImageSpec& spec = m_input->spec();
    m_header.width = spec.width;
    m_header.height = spec.height;
    m_header.depth = spec.depth;
    m_header.channels = spec.nchannels;
    m_header.bitsPerSample =
        spec.get_int_attribute("oiio:BitsPerSample", int(spec.format.size() * 8));
    m_header.isFloat = spec.format.is_floating_point();
    m_header.formatName = m_input->format_name();
    m_header.colorSpaceName = spec.get_string_attribute("oiio:ColorSpace");
    m_header.subimageName = spec.get_string_attribute("oiio:subimagename");
    if (m_header.formatName == "targa")
      m_header.bitsPerSample = targaBitsPerSample(m_path, m_header.bitsPerSample);
    countSubimages();
  }

  const OiioHeader& header() const override { return m_header; }

  Status readImage(int channels, float* pixels) override {
    return readPixels(
        [&] { return m_input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels); },
        true);
  }

  Status verify() override {
    const OIIO::ImageSpec& spec = m_input->spec();
    // Tiled files (VFX pipelines' TIFFs and mip-mapped EXRs) are read a row of tiles at a time:
    // OpenImageIO 2.4's read_scanlines divides by zero on them (SIGFPE). Strips stay aligned to
    // the tile height; the last one ends at the image's edge.
    const bool tiled = spec.tile_width > 0 && spec.tile_height > 0;
    const int stripRows = tiled ? spec.tile_height * std::max(1, 64 / spec.tile_height) : 64;
    const int stripWidth =
        tiled ? (spec.width + spec.tile_width - 1) / spec.tile_width * spec.tile_width : spec.width;
    std::vector<float> strip(std::size_t(stripWidth) * std::size_t(spec.nchannels) *
                             std::size_t(stripRows));
    const int lastRow = spec.y + spec.height;
    for (int y = spec.y; y < lastRow; y += stripRows) {
      const int end = std::min(y + stripRows, lastRow);
      const auto readStrip = [&] {
        if (tiled) {
          return m_input->read_tiles(0, 0, spec.x, spec.x + spec.width, y, end, spec.z,
                                     spec.z + std::max(1, spec.depth), 0, spec.nchannels,
                                     OIIO::TypeDesc::FLOAT, strip.data());
        }
        return m_input->read_scanlines(0, 0, y, end, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                                       strip.data());
      };
      if (Status status = readPixels(readStrip, end == lastRow); !status)
        return status;
    }
    return {};
  }

 private:
  // Runs one pixel read and turns a failure, or a failure reported late on close (a CRC error
  // in the last chunk), into a message naming the file.
  template <class Read>
  Status readPixels(Read read, bool closeAfter) {
    bool ok = false;
    {
      const ThirdPartyAllocationScope oiioMayLeakOnDamagedFiles;
      ok = read();
    }
    if (ok && closeAfter)
      ok = m_input->close() && !m_input->has_error();
    if (!ok) {
      return makeError(m_path + ": the pixel data is damaged or truncated (" +
                       cleanOiioMessage(m_input->geterror()) + ")");
    }
    return {};
  }

  // Multi-part EXRs and multi-page TIFFs: how many there are, so `info` can say that Relief
  // reads the first. The reader is left on the first. A cap keeps a file that claims thousands
  // of parts from costing a seek each (libtiff already refuses loops of pages).
  void countSubimages() {
    constexpr int kMostCounted = 1024;
    int count = 1;
    while (count < kMostCounted && m_input->seek_subimage(count, 0))
      ++count;
    m_header.subimages = count;
    // The failed seek past the last one leaves an error pending (which close() would report as
    // damage) and, in the TIFF reader, its directory moved: clear it and go back to the first.
    (void)m_input->geterror();
    m_input->seek_subimage(0, 0);
  }

  std::string m_path;
  std::unique_ptr<OIIO::ImageInput> m_input;
  OiioHeader m_header;
};

OIIO::TypeDesc typeOf(OiioSampleType type) {
  switch (type) {
    case OiioSampleType::UInt8:
      return OIIO::TypeDesc::UINT8;
    case OiioSampleType::UInt16:
      return OIIO::TypeDesc::UINT16;
    case OiioSampleType::Half:
      return OIIO::TypeDesc::HALF;
    case OiioSampleType::Float:
      return OIIO::TypeDesc::FLOAT;
  }
  return OIIO::TypeDesc::FLOAT;
}

class Module final : public OiioModule {
 public:
  Result<std::unique_ptr<OiioInput>> open(const std::string& path,
                                          const std::string& readerName) override {
    std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create(readerName);
    if (!input) {
      return makeError(path + ": not an image file Relief reads (" +
                       cleanOiioMessage(OIIO::geterror()) + ")");
    }
    bool opened = false;
    {
      const ThirdPartyAllocationScope oiioMayLeakOnDamagedHeaders;
      // Maps keep their alpha as stored: it is data (a packed height, a mask), not coverage to
      // premultiply by, and PNG stores it straight. Without this hint OpenImageIO multiplies the
      // colour of PNG, TGA and unassociated-alpha TIFF files by their alpha on reading.
      OIIO::ImageSpec config;
      config.attribute("oiio:UnassociatedAlpha", 1);
      OIIO::ImageSpec spec;
      opened = input->open(path, spec, config);
    }
    if (!opened) {
      return makeError(path + ": cannot read as an image (" + cleanOiioMessage(input->geterror()) +
                       ")");
    }
    return std::unique_ptr<OiioInput>(std::make_unique<Input>(path, std::move(input)));
  }

  Status write(const std::string& path, const std::string& temporary,
               const OiioWriteRequest& request) override {
    auto output = OIIO::ImageOutput::create(path);
    if (!output) {
      return makeError(path + ": cannot write this file type (" +
                       cleanOiioMessage(OIIO::geterror()) + ")");
    }
    OIIO::ImageSpec spec(request.width, request.height, request.channels,
                         typeOf(request.sampleType));
    // Tag linear data (normals, heights) as such, so readers do not treat it as sRGB colour.
    spec.attribute("oiio:ColorSpace", request.srgb ? "sRGB" : "Linear");
    // Alpha is data and is written as it is (OpenImageIO would otherwise divide the colour by
    // it for formats that store straight alpha, losing whatever exceeds the alpha).
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (request.zip)
      spec.attribute("compression", "zip");
    // Quantising finer data to 8 bits bands smooth gradients; OpenImageIO's dither adds noise
    // of under half a level first.
    if (request.dither)
      spec.attribute("oiio:dither", 1);
    const bool written = output->open(temporary, spec) &&
                         output->write_image(OIIO::TypeDesc::FLOAT, request.pixels) &&
                         output->close();
    if (!written)
      return makeError(path + ": cannot write (" + cleanOiioMessage(output->geterror()) + ")");
    return {};
  }
};

}  // namespace
}  // namespace relief::core::inline image

extern "C" __attribute__((visibility("default"))) relief::core::OiioModule* reliefOiioModule() {
  static relief::core::image::Module module;
  return &module;
}
