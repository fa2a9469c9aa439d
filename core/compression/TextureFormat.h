// The GPU block-compression formats Relief encodes, decodes and writes (reference 003, ch. 2):
// S3TC/BC1-BC3, RGTC/BC4-BC5 (3Dc), DXT5nm, BPTC/BC7, ETC1/ETC2/EAC and ASTC LDR. One table says,
// for each, its name, family, block size, what its channels hold, and its codes in the file formats
// and in GL; everything else (the codec dispatch, the containers, the renderer's feature checks,
// preset parsing) reads these columns. Adding a format is one row here plus its codec.
#pragma once

#include "core/compression/MipChain.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace relief::core::inline compression {

enum class TextureFormat {
  Bc1,         // DXT1: RGB 5:6:5 endpoints, 2-bit indices (alpha 1)
  Bc2,         // DXT3: BC1 colour + explicit 4-bit alpha
  Bc3,         // DXT5: BC1 colour + interpolated alpha
  Bc4,         // ATI1/RGTC1: one channel, interpolated like BC3 alpha
  Bc5,         // ATI2/3Dc/RGTC2: two BC4 channels (normal X, Y; Z rebuilt)
  Dxt5nm,      // BC3 with normal X in alpha and Y in green (reference 003's fallback)
  Bc7,         // BPTC: RGBA in eight block modes with up to three partitioned subsets
  Bc6h,        // BPTC float: RGB half floats, unsigned (HDR colour, environments, float maps)
  Bc6hSigned,  // BPTC float: RGB half floats with sign
  Etc1,        // ETC1: RGB; a valid ETC2 RGB stream
  Etc2,        // ETC2 RGB
  Etc2A,       // ETC2 RGBA: EAC alpha block + ETC2 colour block
  EacR11,      // EAC R11: one channel, 11-bit
  EacRg11,     // EAC RG11: two channels (normal X, Y; Z rebuilt)
  Astc4x4,
  Astc5x5,
  Astc6x6,
  Astc8x8,
  // astcenc's normal-map mode: X in alpha, Y in red, green and blue (its "gggr" swizzle, the
  // DXT5nm layout), two channels that ASTC's luminance-alpha endpoints store well, with the
  // error measured as angles.
  Astc4x4Normal,
  Astc5x5Normal,
  Astc6x6Normal,
  Astc8x8Normal,
};
// How many formats there are (the last one + 1): TextureFormat.cpp's table has a row for each.
inline constexpr std::size_t kTextureFormatCount = std::size_t(TextureFormat::Astc8x8Normal) + 1;

// What the channels of a format carry, which decides how a map is fed to it and read back.
enum class FormatLayout {
  Rgb,       // colour (alpha ignored)
  Rgba,      // colour and alpha
  R,         // one channel in red (height, AO, roughness)
  NormalRg,  // normal X, Y in red, green; Z = sqrt(1 - x^2 - y^2) (reference 003 eq. 2.1)
  NormalAg,  // normal X in alpha, Y in green (DXT5nm)
  RgbHalf,   // RGB half floats (BC6H): linear values beyond 0..1, a single value in all three
};

enum class CompressionQuality { Fast, Normal, Best };

// Which codec family encodes and decodes a format (BlockCodecs.h, AstcCodec.h).
enum class FormatFamily { Bc, Etc, Astc };

// What a GL driver must offer to sample a format natively; the renderer turns it into the
// extension or version check (renderer/CompressedUpload.cpp).
enum class GpuFeature { S3tc, Rgtc, Bptc, Etc2Eac, AstcLdr };

// How KTX2's data format descriptor lists a format's block (Khronos Data Format 1.3, 5.6 and
// ch. 15-17): one sample over the whole block on channel 0 (BC1, BC4, BC7, EAC R11, ASTC) or on
// ETC's colour channel (ETC1, ETC2 RGB), or two 64-bit halves: alpha then BC colour (BC2, BC3,
// DXT5nm), red then green (BC5, EAC RG11), alpha then ETC colour (ETC2 RGBA).
enum class Ktx2Samples { Whole, EtcColour, AlphaThenColour, RedThenGreen, AlphaThenEtcColour };

struct TextureFormatInfo {
  TextureFormat format;
  std::string_view name;   // "bc1", as the CLI and presets spell it
  std::string_view label;  // "BC1 (DXT1)"
  FormatFamily family;
  GpuFeature gpuFeature;
  int blockWidth;
  int blockHeight;
  int bytesPerBlock;
  FormatLayout layout;
  // KTX2 vkFormat (UNORM; the sRGB variant is srgbVkFormat, 0 when there is none).
  std::uint32_t vkFormat;
  std::uint32_t srgbVkFormat;
  // DDS legacy FourCC, 0 when the format has no DDS representation that common readers open
  // (then only KTX2 holds it: containerHolds in TextureFile.h).
  std::uint32_t fourCC;
  // DXGI_FORMAT of the DDS DX10 header (UNORM; the sRGB one, 0 when none); 0 when DirectX has
  // no such format. Formats without a FourCC are written with the DX10 header.
  std::uint32_t dxgiFormat;
  std::uint32_t srgbDxgiFormat;
  // OpenGL internal formats (sRGB 0 when none).
  std::uint32_t glFormat;
  std::uint32_t glSrgbFormat;
  // KTX2's colour model (KHR_DF_MODEL_BC1A 128 ... BC7 134, ETC2 161, ASTC 162) and samples.
  std::uint32_t ktx2ColourModel;
  Ktx2Samples ktx2Samples;
};

// A compression choice: what a map is compressed into. Presets store one per map slot (parsed
// once when read), the CLI builds one from its options, the Compress panel from its rows.
struct CompressionSettings {
  TextureFormat format = TextureFormat::Bc1;
  CompressionQuality quality = CompressionQuality::Normal;
  bool mipmaps = false;
  // Zstandard level (1..22) for the levels of a KTX2 file (supercompression scheme 2); 0 writes
  // them as they are. DDS has no supercompression.
  int zstdLevel = 0;
  // BC1-BC3 colour error weighed by luminance (Rec. 709) instead of alike per channel. Uniform
  // is the default, as in libsquish and rgbcx, so PSNR compares across tools.
  bool perceptual = false;
  // The mip chain's filter (MipChain.h): box, or Kaiser-windowed sinc.
  MipFilter mipFilter = MipFilter::Box;
  // A roughness map's mips widened by the material's normal map's spread (RoughnessFold.h:
  // Toksvig), so a bumpy surface far away stays as rough as its bumps make it look.
  bool roughnessFromNormals = false;
  // A colour map's alpha cutoff (0..1) whose coverage every mip level keeps (MipChain.h:
  // scaleAlphaToCoverage), for cut-outs drawn with an alpha test; 0: off.
  float alphaCoverage = 0.0f;
  // Rate-distortion optimisation for LZ (BlockRdo.h): the squared error accepted per bit saved
  // after Zstandard; 0 (off) writes the encoder's blocks as they are. BC1, BC3, BC4, BC5, BC7.
  float rdoLambda = 0.0f;

  bool operator==(const CompressionSettings&) const = default;
};

// The mip chain a map ships with under `settings` (MipChain.h's MipChainSpec); a map without a
// compression choice ships, as engines import it, with a full box-filtered chain.
MipChainSpec shippedMipChain(const std::optional<CompressionSettings>& settings);

std::span<const TextureFormatInfo> allTextureFormats();
const TextureFormatInfo& textureFormatInfo(TextureFormat format);
std::optional<TextureFormat> findTextureFormat(std::string_view name);
std::string_view compressionQualityName(CompressionQuality quality);
std::optional<CompressionQuality> findCompressionQuality(std::string_view name);

inline constexpr int kMaxZstdLevel = 22;

double bitsPerPixel(TextureFormat format);
bool isTwoChannelNormalFormat(TextureFormat format);  // BC5, DXT5nm, EAC RG11
bool isSingleChannelFormat(TextureFormat format);     // BC4, EAC R11
bool isAstc(TextureFormat format);
// BC6H and its signed form: half floats, judged in float (CompressionMetrics.h: HdrMetrics),
// fed linear values that are not clamped to 0..1, and offered for float maps only.
bool isHalfFloatFormat(TextureFormat format);
bool isBcFamily(TextureFormat format);

constexpr std::uint32_t makeFourCC(char a, char b, char c, char d) {
  return std::uint32_t(std::uint8_t(a)) | std::uint32_t(std::uint8_t(b)) << 8 |
         std::uint32_t(std::uint8_t(c)) << 16 | std::uint32_t(std::uint8_t(d)) << 24;
}

}  // namespace relief::core::inline compression
