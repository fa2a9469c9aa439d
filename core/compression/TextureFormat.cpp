// TextureFormat; see TextureFormat.h. Codes: vkFormat from the Vulkan specification (as KTX2
// uses them), FourCC as DirectX 9 readers know them, GL enums from EXT_texture_compression_s3tc,
// EXT_texture_sRGB, ARB_texture_compression_rgtc, ARB_ES3_compatibility, KHR_texture_compression_
// astc_ldr, ARB_texture_compression_bptc and OES_compressed_ETC1_RGB8_texture; DXGI_FORMAT
// values from Microsoft's DXGI_FORMAT enumeration.
#include "core/compression/TextureFormat.h"

#include <array>

namespace relief::core::inline compression {
namespace {

constexpr std::array<TextureFormatInfo, kTextureFormatCount> kFormats = {{
    {TextureFormat::Bc1, "bc1", "BC1 (DXT1)", FormatFamily::Bc, GpuFeature::S3tc, 4, 4, 8,
     FormatLayout::Rgb, 131, 132, makeFourCC('D', 'X', 'T', '1'), 71, 72, 0x83F0, 0x8C4C, 128,
     Ktx2Samples::Whole},
    {TextureFormat::Bc2, "bc2", "BC2 (DXT3)", FormatFamily::Bc, GpuFeature::S3tc, 4, 4, 16,
     FormatLayout::Rgba, 135, 136, makeFourCC('D', 'X', 'T', '3'), 74, 75, 0x83F2, 0x8C4E, 129,
     Ktx2Samples::AlphaThenColour},
    {TextureFormat::Bc3, "bc3", "BC3 (DXT5)", FormatFamily::Bc, GpuFeature::S3tc, 4, 4, 16,
     FormatLayout::Rgba, 137, 138, makeFourCC('D', 'X', 'T', '5'), 77, 78, 0x83F3, 0x8C4F, 130,
     Ktx2Samples::AlphaThenColour},
    {TextureFormat::Bc4, "bc4", "BC4 (ATI1)", FormatFamily::Bc, GpuFeature::Rgtc, 4, 4, 8,
     FormatLayout::R, 139, 0, makeFourCC('A', 'T', 'I', '1'), 80, 0, 0x8DBB, 0, 131,
     Ktx2Samples::Whole},
    {TextureFormat::Bc5, "bc5", "BC5 (ATI2, 3Dc)", FormatFamily::Bc, GpuFeature::Rgtc, 4, 4, 16,
     FormatLayout::NormalRg, 141, 0, makeFourCC('A', 'T', 'I', '2'), 83, 0, 0x8DBD, 0, 132,
     Ktx2Samples::RedThenGreen},
    {TextureFormat::Dxt5nm, "dxt5nm", "DXT5nm (normal in AG)", FormatFamily::Bc, GpuFeature::S3tc,
     4, 4, 16, FormatLayout::NormalAg, 137, 0, makeFourCC('D', 'X', 'T', '5'), 77, 0, 0x83F3, 0,
     130, Ktx2Samples::AlphaThenColour},
    {TextureFormat::Bc7, "bc7", "BC7 (BPTC)", FormatFamily::Bc, GpuFeature::Bptc, 4, 4, 16,
     FormatLayout::Rgba, 145, 146, 0, 98, 99, 0x8E8C, 0x8E8D, 134, Ktx2Samples::Whole},
    {TextureFormat::Bc6h, "bc6h", "BC6H (BPTC float)", FormatFamily::Bc, GpuFeature::Bptc, 4, 4, 16,
     FormatLayout::RgbHalf, 143, 0, 0, 95, 0, 0x8E8F, 0, 133, Ktx2Samples::Whole},
    {TextureFormat::Bc6hSigned, "bc6h-signed", "BC6H signed (BPTC float)", FormatFamily::Bc,
     GpuFeature::Bptc, 4, 4, 16, FormatLayout::RgbHalf, 144, 0, 0, 96, 0, 0x8E8E, 0, 133,
     Ktx2Samples::Whole},
    {TextureFormat::Etc1, "etc1", "ETC1", FormatFamily::Etc, GpuFeature::Etc2Eac, 4, 4, 8,
     FormatLayout::Rgb, 147, 148, 0, 0, 0, 0x9274, 0x9275, 161, Ktx2Samples::EtcColour},
    {TextureFormat::Etc2, "etc2", "ETC2 RGB", FormatFamily::Etc, GpuFeature::Etc2Eac, 4, 4, 8,
     FormatLayout::Rgb, 147, 148, 0, 0, 0, 0x9274, 0x9275, 161, Ktx2Samples::EtcColour},
    {TextureFormat::Etc2A, "etc2a", "ETC2 RGBA", FormatFamily::Etc, GpuFeature::Etc2Eac, 4, 4, 16,
     FormatLayout::Rgba, 151, 152, 0, 0, 0, 0x9278, 0x9279, 161, Ktx2Samples::AlphaThenEtcColour},
    {TextureFormat::EacR11, "eac-r11", "EAC R11", FormatFamily::Etc, GpuFeature::Etc2Eac, 4, 4, 8,
     FormatLayout::R, 153, 0, 0, 0, 0, 0x9270, 0, 161, Ktx2Samples::Whole},
    {TextureFormat::EacRg11, "eac-rg11", "EAC RG11", FormatFamily::Etc, GpuFeature::Etc2Eac, 4, 4,
     16, FormatLayout::NormalRg, 155, 0, 0, 0, 0, 0x9272, 0, 161, Ktx2Samples::RedThenGreen},
    {TextureFormat::Astc4x4, "astc4x4", "ASTC 4x4", FormatFamily::Astc, GpuFeature::AstcLdr, 4, 4,
     16, FormatLayout::Rgba, 157, 158, 0, 0, 0, 0x93B0, 0x93D0, 162, Ktx2Samples::Whole},
    {TextureFormat::Astc5x5, "astc5x5", "ASTC 5x5", FormatFamily::Astc, GpuFeature::AstcLdr, 5, 5,
     16, FormatLayout::Rgba, 161, 162, 0, 0, 0, 0x93B2, 0x93D2, 162, Ktx2Samples::Whole},
    {TextureFormat::Astc6x6, "astc6x6", "ASTC 6x6", FormatFamily::Astc, GpuFeature::AstcLdr, 6, 6,
     16, FormatLayout::Rgba, 165, 166, 0, 0, 0, 0x93B4, 0x93D4, 162, Ktx2Samples::Whole},
    {TextureFormat::Astc8x8, "astc8x8", "ASTC 8x8", FormatFamily::Astc, GpuFeature::AstcLdr, 8, 8,
     16, FormatLayout::Rgba, 171, 172, 0, 0, 0, 0x93B7, 0x93D7, 162, Ktx2Samples::Whole},
    {TextureFormat::Astc4x4Normal, "astc4x4-normal", "ASTC 4x4 normal (X in A, Y in G)",
     FormatFamily::Astc, GpuFeature::AstcLdr, 4, 4, 16, FormatLayout::NormalAg, 157, 0, 0, 0, 0,
     0x93B0, 0, 162, Ktx2Samples::Whole},
    {TextureFormat::Astc5x5Normal, "astc5x5-normal", "ASTC 5x5 normal (X in A, Y in G)",
     FormatFamily::Astc, GpuFeature::AstcLdr, 5, 5, 16, FormatLayout::NormalAg, 161, 0, 0, 0, 0,
     0x93B2, 0, 162, Ktx2Samples::Whole},
    {TextureFormat::Astc6x6Normal, "astc6x6-normal", "ASTC 6x6 normal (X in A, Y in G)",
     FormatFamily::Astc, GpuFeature::AstcLdr, 6, 6, 16, FormatLayout::NormalAg, 165, 0, 0, 0, 0,
     0x93B4, 0, 162, Ktx2Samples::Whole},
    {TextureFormat::Astc8x8Normal, "astc8x8-normal", "ASTC 8x8 normal (X in A, Y in G)",
     FormatFamily::Astc, GpuFeature::AstcLdr, 8, 8, 16, FormatLayout::NormalAg, 171, 0, 0, 0, 0,
     0x93B7, 0, 162, Ktx2Samples::Whole},
}};

// textureFormatInfo indexes the table by the enum: each row must sit at its enum's position.
constexpr bool rowsInEnumOrder() {
  for (std::size_t i = 0; i < kFormats.size(); ++i) {
    if (std::size_t(kFormats[i].format) != i)
      return false;
  }
  return true;
}
static_assert(rowsInEnumOrder(), "kFormats rows must follow the TextureFormat enum's order");

}  // namespace

std::span<const TextureFormatInfo> allTextureFormats() {
  return kFormats;
}

const TextureFormatInfo& textureFormatInfo(TextureFormat format) {
  return kFormats[std::size_t(format)];
}

std::optional<TextureFormat> findTextureFormat(std::string_view name) {
  for (const TextureFormatInfo& info : kFormats) {
    if (info.name == name)
      return info.format;
  }
  return std::nullopt;
}

std::string_view compressionQualityName(CompressionQuality quality) {
  switch (quality) {
    case CompressionQuality::Fast:
      return "fast";
    case CompressionQuality::Normal:
      return "normal";
    case CompressionQuality::Best:
      return "best";
  }
  return "normal";
}

std::optional<CompressionQuality> findCompressionQuality(std::string_view name) {
  for (CompressionQuality quality :
       {CompressionQuality::Fast, CompressionQuality::Normal, CompressionQuality::Best}) {
    if (compressionQualityName(quality) == name)
      return quality;
  }
  return std::nullopt;
}

double bitsPerPixel(TextureFormat format) {
  const TextureFormatInfo& info = textureFormatInfo(format);
  return 8.0 * info.bytesPerBlock / (info.blockWidth * info.blockHeight);
}

bool isTwoChannelNormalFormat(TextureFormat format) {
  const FormatLayout layout = textureFormatInfo(format).layout;
  return layout == FormatLayout::NormalRg || layout == FormatLayout::NormalAg;
}

bool isSingleChannelFormat(TextureFormat format) {
  return textureFormatInfo(format).layout == FormatLayout::R;
}

bool isAstc(TextureFormat format) {
  return textureFormatInfo(format).family == FormatFamily::Astc;
}

bool isHalfFloatFormat(TextureFormat format) {
  return textureFormatInfo(format).layout == FormatLayout::RgbHalf;
}

bool isBcFamily(TextureFormat format) {
  return textureFormatInfo(format).family == FormatFamily::Bc;
}

MipChainSpec shippedMipChain(const std::optional<CompressionSettings>& settings) {
  if (!settings)
    return {};
  return {settings->mipmaps, settings->mipFilter, settings->roughnessFromNormals,
          settings->alphaCoverage};
}

}  // namespace relief::core::inline compression
