// DDS reading and writing; see TextureFile.h. Layout from Microsoft's "DDS" programming guide:
// "DDS " magic, DDS_HEADER (124 bytes) with DDS_PIXELFORMAT (32 bytes), an optional
// DDS_HEADER_DXT10 (20 bytes) when the FourCC is "DX10", then level 0 and the smaller levels
// in order.
#include "core/compression/ByteStream.h"
#include "core/compression/MipChain.h"
#include "core/compression/TextureFile.h"

#include <algorithm>

namespace relief::core::inline compression {
namespace {

constexpr std::uint32_t kMagic = makeFourCC('D', 'D', 'S', ' ');
constexpr std::uint32_t kHeaderSize = 124, kPixelFormatSize = 32;
// DDS_HEADER flags.
constexpr std::uint32_t kCaps = 0x1, kHeight = 0x2, kWidth = 0x4, kPixelFormat = 0x1000,
                        kMipMapCount = 0x20000, kLinearSize = 0x80000;
// DDS_PIXELFORMAT flags: FourCC, and NVIDIA's mark for a normal map (how DXT5nm is told apart).
constexpr std::uint32_t kFourCCFlag = 0x4, kNormalFlag = 0x80000000u;
// dwCaps.
constexpr std::uint32_t kCapsComplex = 0x8, kCapsTexture = 0x1000, kCapsMipMap = 0x400000;

// The format a DXGI_FORMAT code names: the table's UNORM and sRGB codes, and the TYPELESS code
// that precedes the UNORM one for every BC format (BC1 70, ..., BC7 97; BC6H's 94 precedes
// UF16 95, and SF16 96 follows). DXT5nm shares BC3's codes, and BC3 comes first in the table;
// BC6H (unsigned) comes before its signed form, so 95 is never read as SF16's "typeless".
std::optional<TextureFormat> formatForDxgi(std::uint32_t code, bool& srgb) {
  for (const TextureFormatInfo& info : allTextureFormats()) {
    if (info.dxgiFormat == 0)
      continue;
    if (code == info.dxgiFormat || code == info.dxgiFormat - 1 ||
        (info.srgbDxgiFormat != 0 && code == info.srgbDxgiFormat)) {
      srgb = code == info.srgbDxgiFormat;
      return info.format;
    }
  }
  return std::nullopt;
}

std::optional<TextureFormat> formatForFourCC(std::uint32_t fourCC, bool normalFlag) {
  switch (fourCC) {
    case makeFourCC('D', 'X', 'T', '1'):
      return TextureFormat::Bc1;
    case makeFourCC('D', 'X', 'T', '2'):
    case makeFourCC('D', 'X', 'T', '3'):
      return TextureFormat::Bc2;
    case makeFourCC('D', 'X', 'T', '4'):
    case makeFourCC('D', 'X', 'T', '5'):
      return normalFlag ? TextureFormat::Dxt5nm : TextureFormat::Bc3;
    case makeFourCC('A', 'T', 'I', '1'):
    case makeFourCC('B', 'C', '4', 'U'):
      return TextureFormat::Bc4;
    case makeFourCC('A', 'T', 'I', '2'):
    case makeFourCC('B', 'C', '5', 'U'):
      return TextureFormat::Bc5;
    default:
      return std::nullopt;
  }
}

std::string fourCCText(std::uint32_t fourCC) {
  std::string text;
  for (int i = 0; i < 4; ++i) {
    const char c = char((fourCC >> (8 * i)) & 0xFF);
    text += (c >= 32 && c < 127) ? c : '?';
  }
  return text;
}

}  // namespace

Result<std::vector<std::uint8_t>> encodeDdsHeader(const CompressedTexture& texture) {
  const TextureFormatInfo& info = textureFormatInfo(texture.format);
  if (!containerHolds(TextureContainer::Dds, texture.format)) {
    return makeError(std::string(info.label) +
                     " has no DDS format that common readers open; save it as .ktx2");
  }
  if (texture.levels.empty())
    return makeError("the texture has no levels");
  const CompressedLevel& base = texture.levels.front();
  const bool mips = texture.levels.size() > 1;
  ByteWriter out;
  out.u32(kMagic);
  out.u32(kHeaderSize);
  out.u32(kCaps | kHeight | kWidth | kPixelFormat | kLinearSize | (mips ? kMipMapCount : 0));
  out.u32(std::uint32_t(base.height));
  out.u32(std::uint32_t(base.width));
  out.u32(std::uint32_t(base.data.size()));  // linear size of level 0
  out.u32(0);                                // depth
  out.u32(std::uint32_t(texture.levels.size()));
  out.zeros(11 * 4);  // reserved
  // Formats without a legacy FourCC (BC7) take the DX10 header, which also says sRGB.
  const bool dx10 = info.fourCC == 0;
  out.u32(kPixelFormatSize);
  out.u32(kFourCCFlag | (texture.format == TextureFormat::Dxt5nm ? kNormalFlag : 0));
  out.u32(dx10 ? makeFourCC('D', 'X', '1', '0') : info.fourCC);
  out.zeros(5 * 4);  // bit count and masks: unused with a FourCC
  out.u32(kCapsTexture | (mips ? kCapsComplex | kCapsMipMap : 0));
  out.zeros(4 * 4);  // caps2, caps3, caps4, reserved2
  if (dx10) {
    // DDS_HEADER_DXT10: format, D3D10_RESOURCE_DIMENSION_TEXTURE2D, no flags, one texture, and
    // alpha mode 0 (unknown: straight alpha, as every reader assumes).
    out.u32(texture.srgb && info.srgbDxgiFormat != 0 ? info.srgbDxgiFormat : info.dxgiFormat);
    out.u32(3);
    out.u32(0);
    out.u32(1);
    out.u32(0);
  }
  return std::move(out.data());
}

Result<std::vector<std::uint8_t>> encodeDds(const CompressedTexture& texture) {
  Result<std::vector<std::uint8_t>> header = encodeDdsHeader(texture);
  if (!header)
    return header;
  std::vector<std::uint8_t> bytes = std::move(header).value();
  for (const CompressedLevel& level : texture.levels)
    bytes.insert(bytes.end(), level.data.begin(), level.data.end());
  return bytes;
}

Result<CompressedTexture> decodeDds(const std::vector<std::uint8_t>& bytes,
                                    const std::string& name) {
  const auto fail = [&name](const std::string& problem) { return fileError(name, problem); };
  ByteReader in(bytes);
  if (in.u32() != kMagic)
    return fail("not a DDS file (no \"DDS \" signature)");
  const std::uint32_t headerSize = in.u32();
  in.skip(4);  // flags: readers in practice ignore them, so do we
  const std::uint32_t height = in.u32(), width = in.u32();
  in.skip(4);  // pitch or linear size
  const std::uint32_t depth = in.u32();
  const std::uint32_t mipCount = in.u32();
  in.skip(11 * 4);
  const std::uint32_t pixelFormatSize = in.u32(), pixelFormatFlags = in.u32(), fourCC = in.u32();
  in.skip(5 * 4 + 4);  // bit count and masks, caps
  const std::uint32_t caps2 = in.u32();
  in.skip(3 * 4);  // caps3, caps4, reserved
  if (!in.ok())
    return fail("the file is shorter than a DDS header (" + std::to_string(bytes.size()) +
                " bytes)");
  if (headerSize != kHeaderSize || pixelFormatSize != kPixelFormatSize)
    return fail("the DDS header sizes are wrong (" + std::to_string(headerSize) + ", " +
                std::to_string(pixelFormatSize) + ")");
  if (!(pixelFormatFlags & kFourCCFlag))
    return fail("holds uncompressed texels; only block-compressed DDS files are read");
  // A cube map or a volume read as 2D would show one face or slice as if it were the map.
  constexpr std::uint32_t kCubeMap = 0x200, kVolume = 0x200000;
  if (caps2 & kCubeMap)
    return fail("is a cube map; only single 2D textures are read");
  if ((caps2 & kVolume) || depth > 1)
    return fail("is a volume texture (depth " + std::to_string(depth) +
                "); only single 2D textures are read");

  std::optional<TextureFormat> format;
  bool srgb = false;
  if (fourCC == makeFourCC('D', 'X', '1', '0')) {
    const std::uint32_t dxgi = in.u32();
    const std::uint32_t dimension = in.u32();
    const std::uint32_t miscFlag = in.u32();
    const std::uint32_t arraySize = in.u32();
    in.skip(4);
    if (!in.ok())
      return fail("the DX10 header is cut short");
    format = formatForDxgi(dxgi, srgb);
    if (!format) {
      return fail("DXGI format " + std::to_string(dxgi) +
                  " is not one Relief reads (BC1-BC5, BC7)");
    }
    constexpr std::uint32_t kTextureCube = 0x4;
    // arraySize 0 is no texture at all (DDS_HEADER_DXT10: "must be at least 1").
    if (dimension != 3 || arraySize != 1 || (miscFlag & kTextureCube))
      return fail("only single 2D textures are read (not arrays, cube maps or volumes)");
  } else {
    format = formatForFourCC(fourCC, pixelFormatFlags & kNormalFlag);
    if (!format)
      return fail("FourCC \"" + fourCCText(fourCC) + "\" is not one Relief reads");
  }
  if (std::string problem = textureExtentProblem(width, height, mipCount); !problem.empty())
    return fail(problem);
  const int levels = int(std::max<std::uint32_t>(mipCount, 1));

  CompressedTexture texture = textureOfUnknownOrigin(*format, srgb);
  std::uint64_t offset = in.position();
  int w = int(width), h = int(height);
  for (int level = 0; level < levels; ++level) {
    const std::uint64_t size = compressedLevelSize(*format, w, h);
    if (size > bytes.size() - std::min<std::uint64_t>(offset, bytes.size())) {
      return fail("the file ends inside mip level " + std::to_string(level) + " (needs " +
                  std::to_string(offset + size) + " bytes, has " + std::to_string(bytes.size()) +
                  ")");
    }
    CompressedLevel compressed{w, h, {}};
    compressed.data.assign(bytes.begin() + std::ptrdiff_t(offset),
                           bytes.begin() + std::ptrdiff_t(offset + size));
    texture.levels.push_back(std::move(compressed));
    offset += size;
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
  }
  return texture;
}

}  // namespace relief::core::inline compression
