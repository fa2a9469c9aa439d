// ImageConversion; see ImageConversion.h.
#include "renderer/ImageConversion.h"

#include <algorithm>
#include <cmath>

namespace relief::renderer {

QImage makeThumbnail(const core::Image& image, int size) {
  if (image.isEmpty() || size < 1)
    return {};
  const double scale = double(size) / double(std::max(image.width(), image.height()));
  const int width = std::max(1, int(std::lround(image.width() * std::min(scale, 1.0))));
  const int height = std::max(1, int(std::lround(image.height() * std::min(scale, 1.0))));
  QImage thumbnail(width, height, QImage::Format_RGB32);
  const int channels = image.channels();
  for (int ty = 0; ty < height; ++ty) {
    const int y0 = ty * image.height() / height;
    const int y1 = std::max(y0 + 1, (ty + 1) * image.height() / height);
    auto* line = reinterpret_cast<QRgb*>(thumbnail.scanLine(ty));
    for (int tx = 0; tx < width; ++tx) {
      const int x0 = tx * image.width() / width;
      const int x1 = std::max(x0 + 1, (tx + 1) * image.width() / width);
      // Average a few samples of the covered box; a sparse grid keeps 8K maps quick.
      const int stepX = std::max(1, (x1 - x0) / 4);
      const int stepY = std::max(1, (y1 - y0) / 4);
      double sum[3] = {0.0, 0.0, 0.0};
      int count = 0;
      for (int y = y0; y < y1; y += stepY) {
        for (int x = x0; x < x1; x += stepX) {
          const float* pixel = image.pixel(x, y);
          for (int c = 0; c < 3; ++c)
            sum[c] += pixel[channels >= 3 ? c : 0];
          ++count;
        }
      }
      auto to8 = [&](int c) {
        return int(std::lround(std::clamp(sum[c] / count, 0.0, 1.0) * 255.0));
      };
      line[tx] = qRgb(to8(0), to8(1), to8(2));
    }
  }
  return thumbnail;
}

QImage toDisplayImage(const core::Image& image, std::optional<int> channel) {
  if (image.isEmpty())
    return {};
  const int channels = image.channels();
  const bool alpha = channels == 4 && !channel;
  QImage result(image.width(), image.height(),
                alpha ? QImage::Format_RGBA8888 : QImage::Format_RGBX8888);
  const auto to8 = [](float v) { return uchar(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  for (int y = 0; y < image.height(); ++y) {
    uchar* line = result.scanLine(y);
    for (int x = 0; x < image.width(); ++x) {
      const float* texel = image.pixel(x, y);
      uchar* out = line + 4 * x;
      if (channel) {
        out[0] = out[1] = out[2] = to8(texel[std::clamp(*channel, 0, channels - 1)]);
      } else if (channels >= 3) {
        for (int c = 0; c < 3; ++c)
          out[c] = to8(texel[c]);
      } else if (channels == 2) {
        out[0] = to8(texel[0]);
        out[1] = to8(texel[1]);
        out[2] = 0;
      } else {
        out[0] = out[1] = out[2] = to8(texel[0]);
      }
      out[3] = alpha ? to8(texel[3]) : 255;
    }
  }
  return result;
}

core::Image fromQImage(const QImage& picture, core::ColorSpace space) {
  const QImage rgba = picture.convertToFormat(QImage::Format_RGBA8888);
  core::Image image(rgba.width(), rgba.height(), 4, space);
  for (int y = 0; y < rgba.height(); ++y) {
    const uchar* line = rgba.constScanLine(y);
    float* out = image.pixel(0, y);
    for (int i = 0; i < rgba.width() * 4; ++i)
      out[i] = float(line[i]) / 255.0f;
  }
  return image;
}

}  // namespace relief::renderer
