// Small previews of core::Images for panels (QImage lives in the UI layer, not in core).
#pragma once

#include "core/Image.h"

#include <QImage>

#include <optional>

namespace relief::ui {

// Box-filtered preview that fits in size x size; grey images show as grey, values clamped to
// [0, 1] and shown as stored (sRGB colour as sRGB, data maps as their raw values).
QImage makeThumbnail(const core::Image& image, int size);

// The whole image at full size, as stored: RGB(A) as colour (alpha kept), one channel as grey,
// two channels as red and green. With `channel` only that channel, as grey.
QImage toDisplayImage(const core::Image& image, std::optional<int> channel = std::nullopt);

}  // namespace relief::ui
