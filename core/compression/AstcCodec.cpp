// AstcCodec; see AstcCodec.h.
#include "core/compression/AstcCodec.h"

#include <astcenc.h>

#include <QThread>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <thread>

namespace relief::core::inline compression {
namespace {

struct ContextDeleter {
  void operator()(astcenc_context* context) const { astcenc_context_free(context); }
};
using Context = std::unique_ptr<astcenc_context, ContextDeleter>;

float preset(CompressionQuality quality) {
  switch (quality) {
    case CompressionQuality::Fast:
      return ASTCENC_PRE_FAST;
    case CompressionQuality::Normal:
      return ASTCENC_PRE_MEDIUM;
    case CompressionQuality::Best:
      return ASTCENC_PRE_THOROUGH;
  }
  return ASTCENC_PRE_MEDIUM;
}

Result<Context> makeContext(TextureFormat format, bool srgb, float quality, unsigned flags,
                            unsigned threads) {
  const TextureFormatInfo& info = textureFormatInfo(format);
  astcenc_config config{};
  astcenc_error status =
      astcenc_config_init(srgb ? ASTCENC_PRF_LDR_SRGB : ASTCENC_PRF_LDR, unsigned(info.blockWidth),
                          unsigned(info.blockHeight), 1, quality, flags, &config);
  if (status != ASTCENC_SUCCESS)
    return makeError(std::string("astcenc: ") + astcenc_get_error_string(status));
  astcenc_context* context = nullptr;
  status = astcenc_context_alloc(&config, threads, &context);
  if (status != ASTCENC_SUCCESS)
    return makeError(std::string("astcenc: ") + astcenc_get_error_string(status));
  return Context(context);
}

}  // namespace

Result<std::vector<std::uint8_t>> encodeAstc(TextureFormat format, CompressionQuality quality,
                                             bool srgb, const Image& rgba,
                                             const WorkControl& control) {
  const TextureFormatInfo& info = textureFormatInfo(format);
  const unsigned threads = unsigned(std::max(1, QThread::idealThreadCount()));
  // Normal formats: astcenc's normal mode (angular error; X and Y as two channels), stored with
  // its "gggr" swizzle so the blocks hold the DXT5nm layout (Y in R, G, B and X in alpha) from
  // the prepared X, Y in red and green.
  const bool normal = info.layout == FormatLayout::NormalAg;
  Result<Context> context =
      makeContext(format, srgb, preset(quality), normal ? ASTCENC_FLG_MAP_NORMAL : 0, threads);
  if (!context)
    return makeError(context.error());

  const int width = rgba.width(), height = rgba.height();
  std::vector<std::uint8_t> texels(std::size_t(width) * std::size_t(height) * 4);
  for (std::size_t i = 0; i < texels.size(); ++i) {
    texels[i] = std::uint8_t(std::lround(std::clamp(rgba.data()[i], 0.0f, 1.0f) * 255.0f));
  }
  const int blocksX = (width + info.blockWidth - 1) / info.blockWidth;
  const int blockRows = (height + info.blockHeight - 1) / info.blockHeight;
  std::vector<std::uint8_t> out(std::size_t(blocksX) * std::size_t(blockRows) * 16);
  const astcenc_swizzle swizzle =
      normal ? astcenc_swizzle{ASTCENC_SWZ_G, ASTCENC_SWZ_G, ASTCENC_SWZ_G, ASTCENC_SWZ_R}
             : astcenc_swizzle{ASTCENC_SWZ_R, ASTCENC_SWZ_G, ASTCENC_SWZ_B, ASTCENC_SWZ_A};
  constexpr int kStripBlockRows = 16;
  for (int firstRow = 0; firstRow < blockRows; firstRow += kStripBlockRows) {
    if (control.cancelled())
      return makeError("cancelled");
    const int rows = std::min(kStripBlockRows, blockRows - firstRow);
    const int y0 = firstRow * info.blockHeight;
    const int stripHeight = std::min(rows * info.blockHeight, height - y0);
    void* slice = texels.data() + std::size_t(y0) * std::size_t(width) * 4;
    astcenc_image image{unsigned(width), unsigned(stripHeight), 1, ASTCENC_TYPE_U8, &slice};
    std::uint8_t* stripOut = out.data() + std::size_t(firstRow) * std::size_t(blocksX) * 16;
    const std::size_t stripBytes = std::size_t(rows) * std::size_t(blocksX) * 16;
    std::vector<astcenc_error> results(threads, ASTCENC_SUCCESS);
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t) {
      workers.emplace_back([&, t] {
        results[t] =
            astcenc_compress_image(context->get(), &image, &swizzle, stripOut, stripBytes, t);
      });
    }
    for (std::thread& worker : workers)
      worker.join();
    for (astcenc_error status : results) {
      if (status != ASTCENC_SUCCESS)
        return makeError(std::string("astcenc: ") + astcenc_get_error_string(status));
    }
    astcenc_compress_reset(context->get());
    control.report(double(firstRow + rows) / blockRows);
  }
  return out;
}

Result<Image> decodeAstc(TextureFormat format, bool srgb, const std::uint8_t* data,
                         std::size_t size, int width, int height) {
  Result<Context> context =
      makeContext(format, srgb, ASTCENC_PRE_FASTEST, ASTCENC_FLG_DECOMPRESS_ONLY, 1);
  if (!context)
    return makeError(context.error());
  std::vector<std::uint8_t> texels(std::size_t(width) * std::size_t(height) * 4);
  void* slice = texels.data();
  astcenc_image image{unsigned(width), unsigned(height), 1, ASTCENC_TYPE_U8, &slice};
  const astcenc_swizzle swizzle{ASTCENC_SWZ_R, ASTCENC_SWZ_G, ASTCENC_SWZ_B, ASTCENC_SWZ_A};
  const astcenc_error status =
      astcenc_decompress_image(context->get(), data, size, &image, &swizzle, 0);
  if (status != ASTCENC_SUCCESS)
    return makeError(std::string("astcenc: ") + astcenc_get_error_string(status));
  Image decoded(width, height, 4, srgb ? ColorSpace::Srgb : ColorSpace::Linear);
  for (std::size_t i = 0; i < texels.size(); ++i)
    decoded.data()[i] = float(texels[i]) / 255.0f;
  return decoded;
}

}  // namespace relief::core::inline compression
