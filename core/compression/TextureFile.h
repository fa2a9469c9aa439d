// Compressed textures in files: DDS (DirectDraw Surface) and KTX2 (Khronos KTX 2.0).
//
// DDS is written with the legacy FourCC codes every reader knows (DXT1, DXT3, DXT5, ATI1,
// ATI2; DXT5nm is DXT5 with the DDPF_NORMAL flag NVIDIA's tools set) where a format has one,
// and with the DX10 header and its DXGI code otherwise (BC7: 98, sRGB 99), so it holds the BC
// formats only; files with the DX10 header and DXGI BC1-BC5 and BC7 codes are read too. KTX2 holds
// every format by its vkFormat, with a Data Format Descriptor and the mip levels stored smallest
// first, as the KTX 2.0 specification requires.
//
// Readers treat the file as hostile: dimensions and level counts are bounded, sizes are
// computed in 64 bits and checked against the file length before anything is allocated or
// read, and every failure names the file and what is wrong with it.
#pragma once

#include "core/base/Result.h"
#include "core/compression/Compressor.h"
#include "core/image/Image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace relief::core::inline compression {

// The largest width or height a reader accepts: the same limit as for images, because every
// texture is decoded into an Image at some point (a larger one was accepted here and then
// aborted on allocation when decoded).
inline constexpr int kMaxTextureDimension = kMaxImageDimension;
// A 16384x16384 texture of 16 bytes per 4x4 block with its mips is 341 MiB; 2 GiB leaves room
// for uncompressed-size formats a later version may read, and refuses nonsense before reading.
inline constexpr std::uintmax_t kMaxTextureFileBytes = std::uintmax_t(2) << 30;

// The header checks the DDS and KTX2 readers share: a size within 1..kMaxTextureDimension and no
// more mip levels than the size has (`levels` as the file states it). Empty when they hold.
std::string textureExtentProblem(std::uint32_t width, std::uint32_t height, std::uint32_t levels);

enum class TextureContainer { Dds, Ktx2 };

struct TextureContainerInfo {
  TextureContainer container;
  std::string_view extension;  // lower case, without the dot
  std::string_view label;
};
const TextureContainerInfo& textureContainerInfo(TextureContainer container);

// From the extension (.dds, .ktx2), case-insensitive.
std::optional<TextureContainer> containerForPath(const std::string& path);

// Whether a container can hold a format: KTX2 holds every format; DDS the BC family.
bool containerHolds(TextureContainer container, TextureFormat format);
// The container a format is written in when the user prefers DDS where it can hold it.
TextureContainer containerFor(TextureFormat format, bool preferDds);
std::string containerExtension(TextureContainer container);  // ".dds", ".ktx2"

// The file's bytes; `name` appears in error messages.
Result<std::vector<std::uint8_t>> encodeDds(const CompressedTexture& texture);
// The DDS file's header alone: encodeDds is it followed by every level's blocks.
Result<std::vector<std::uint8_t>> encodeDdsHeader(const CompressedTexture& texture);
Result<CompressedTexture> decodeDds(const std::vector<std::uint8_t>& bytes,
                                    const std::string& name);
// zstdLevel 1..22 supercompresses each level with Zstandard (KTX2 scheme 2); 0 does not.
std::vector<std::uint8_t> encodeKtx2(const CompressedTexture& texture, int zstdLevel = 0);
Result<CompressedTexture> decodeKtx2(const std::vector<std::uint8_t>& bytes,
                                     const std::string& name);

// Chooses the container by extension. Saving is atomic: a failed save leaves an existing file
// as it was.
// zstdLevel as for encodeKtx2; a DDS path with a level is refused (DDS has no supercompression).
Status saveCompressedTexture(const CompressedTexture& texture, const std::string& path,
                             int zstdLevel = 0);
Result<CompressedTexture> loadCompressedTexture(const std::string& path);

}  // namespace relief::core::inline compression
