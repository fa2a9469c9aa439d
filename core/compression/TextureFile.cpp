// Choosing the container and moving bytes to and from disk; see TextureFile.h.
#include "core/compression/TextureFile.h"

#include "core/base/AtomicFile.h"
#include "core/base/InputFile.h"
#include "core/base/Text.h"
#include "core/compression/MipChain.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace relief::core::inline compression {
namespace {

constexpr std::array kContainers = {
    TextureContainerInfo{TextureContainer::Dds, "dds", "DDS"},
    TextureContainerInfo{TextureContainer::Ktx2, "ktx2", "KTX2"},
};

}  // namespace

std::optional<TextureContainer> containerForPath(const std::string& path) {
  const std::string extension = lowerExtension(path);
  for (const TextureContainerInfo& info : kContainers) {
    if (info.extension == extension)
      return info.container;
  }
  return std::nullopt;
}

const TextureContainerInfo& textureContainerInfo(TextureContainer container) {
  return kContainers[std::size_t(container)];
}

std::string textureExtentProblem(std::uint32_t width, std::uint32_t height, std::uint32_t levels) {
  if (width == 0 || height == 0 || width > std::uint32_t(kMaxTextureDimension) ||
      height > std::uint32_t(kMaxTextureDimension)) {
    return "its size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1.." +
           std::to_string(kMaxTextureDimension);
  }
  if (levels > std::uint32_t(mipLevelCount(int(width), int(height)))) {
    return std::to_string(levels) + " mip levels is more than a " + std::to_string(width) + "x" +
           std::to_string(height) + " texture has";
  }
  return {};
}

bool containerHolds(TextureContainer container, TextureFormat format) {
  // DDS by the format table's FourCC and DXGI columns: a legacy FourCC, or the DX10 header.
  const TextureFormatInfo& info = textureFormatInfo(format);
  return container == TextureContainer::Ktx2 || info.fourCC != 0 || info.dxgiFormat != 0;
}

TextureContainer containerFor(TextureFormat format, bool preferDds) {
  return preferDds && containerHolds(TextureContainer::Dds, format) ? TextureContainer::Dds
                                                                    : TextureContainer::Ktx2;
}

std::string containerExtension(TextureContainer container) {
  return "." + std::string(textureContainerInfo(container).extension);
}

Status saveCompressedTexture(const CompressedTexture& texture, const std::string& path,
                             int zstdLevel) {
  const std::optional<TextureContainer> container = containerForPath(path);
  if (!container)
    return makeError(path + ": compressed textures are saved as .dds or .ktx2");
  const auto view = [](const std::vector<std::uint8_t>& bytes) {
    return std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  };
  if (*container == TextureContainer::Dds) {
    if (zstdLevel > 0)
      return makeError(path + ": Zstandard supercompression is a KTX2 feature; DDS has none");
    // The header, then the levels' blocks where they are: joined, a 4096^2 BC7 map's 16 MB would
    // be copied once more (and its fresh pages faulted in) only to be written.
    Result<std::vector<std::uint8_t>> header = encodeDdsHeader(texture);
    if (!header)
      return makeError(path + ": " + header.error());
    std::vector<std::string_view> pieces{view(header.value())};
    for (const CompressedLevel& level : texture.levels)
      pieces.push_back(view(level.data));
    return writeFileAtomically(path, pieces);
  }
  return writeFileAtomically(path, view(encodeKtx2(texture, zstdLevel)));
}

Result<CompressedTexture> loadCompressedTexture(const std::string& path) {
  const std::optional<TextureContainer> container = containerForPath(path);
  if (!container)
    return makeError(path + ": not a .dds or .ktx2 file");
  // Bounded by what a largest legal texture could need, so a huge file is refused before it is
  // read into memory (a FIFO or a device before it is opened).
  const Result<std::uintmax_t> size = checkInputFile(path, kMaxTextureFileBytes, "texture");
  if (!size)
    return makeError(size.error());
  std::ifstream file(path, std::ios::binary);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size.value()));
  if (!file || !file.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size())))
    return makeError(path + ": could not be read (" + std::strerror(errno) + ")");
  return *container == TextureContainer::Dds ? decodeDds(bytes, path) : decodeKtx2(bytes, path);
}

}  // namespace relief::core::inline compression
