// core::Image to and from QImage, written once for the CLI (legends), the panels (thumbnails,
// 2D comparison) and the tests (grabbed frames). QImage is QtGui, so this lives above core.
#pragma once

#include "core/image/Image.h"

#include <QImage>

#include <optional>

namespace relief::renderer {

// Box-filtered preview that fits in size x size; grey images show as grey, values clamped to
// [0, 1] and shown as stored (sRGB colour as sRGB, data maps as their raw values).
QImage makeThumbnail(const core::Image& image, int size);

// The whole image at full size, as stored: RGB(A) as colour (alpha kept), one channel as grey,
// two channels as red and green. With `channel` only that channel, as grey.
QImage toDisplayImage(const core::Image& image, std::optional<int> channel = std::nullopt);

// 8-bit RGBA values as floats 0..1 (a grabbed frame, a painted legend), tagged `space`.
core::Image fromQImage(const QImage& picture, core::ColorSpace space = core::ColorSpace::Srgb);

}  // namespace relief::renderer
