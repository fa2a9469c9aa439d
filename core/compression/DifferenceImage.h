// Pictures of where two versions of a map differ, for the compare view: the absolute difference
// amplified by a gain (x1 to x100), and the thresholded form of reference 003's figures (white
// where any compared channel differs by more than the threshold, black elsewhere). Either can
// isolate one channel.
#pragma once

#include "core/image/Image.h"

#include <optional>

namespace relief::core::inline compression {

// `channel` empty: all channels of the reference (up to 4). The result has as many channels as
// compared for the gain form, one for the thresholded form; values 0..1.
Image amplifiedDifference(const Image& reference, const Image& candidate, double gain,
                          std::optional<int> channel = std::nullopt);
// `threshold` in the maps' 0..1 units (8/255 is "more than 8 levels").
Image thresholdedDifference(const Image& reference, const Image& candidate, double threshold,
                            std::optional<int> channel = std::nullopt);

// The root-mean-square difference over each block of blockWidth x blockHeight texels (the
// format's blocks: which blocks the encoder got wrong), one value a block, over the compared
// channels; edge blocks cover what is left of the map. One channel, ceil(w / bw) x ceil(h / bh).
Image blockError(const Image& reference, const Image& candidate, int blockWidth, int blockHeight,
                 std::optional<int> channel = std::nullopt);

}  // namespace relief::core::inline compression
