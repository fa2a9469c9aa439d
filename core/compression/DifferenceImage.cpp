// DifferenceImage; see DifferenceImage.h.
#include "core/compression/DifferenceImage.h"

#include "core/base/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace relief::core::inline compression {
namespace {

// The channels compared: one, or all the reference has that the candidate has too.
std::pair<int, int> channelRange(const Image& reference, const Image& candidate,
                                 std::optional<int> channel) {
  const int count = std::min({reference.channels(), candidate.channels(), 4});
  if (channel)
    return {std::clamp(*channel, 0, count - 1), std::clamp(*channel, 0, count - 1) + 1};
  return {0, count};
}

bool sameSize(const Image& a, const Image& b) {
  return a.width() == b.width() && a.height() == b.height() && !a.isEmpty();
}

}  // namespace

Image amplifiedDifference(const Image& reference, const Image& candidate, double gain,
                          std::optional<int> channel) {
  if (!sameSize(reference, candidate))
    return {};
  // Not a structured binding: clang before 16 cannot capture those in the lambda below.
  const std::pair<int, int> range = channelRange(reference, candidate, channel);
  const int first = range.first;
  const int last = range.second;
  Image out(reference.width(), reference.height(), last - first);
  parallelFor(reference.height(), [&](int y) {
    for (int x = 0; x < reference.width(); ++x) {
      for (int c = first; c < last; ++c) {
        const double d = std::abs(double(reference.at(x, y, c)) - double(candidate.at(x, y, c)));
        out.at(x, y, c - first) = float(std::min(1.0, d * gain));
      }
    }
  });
  return out;
}

Image thresholdedDifference(const Image& reference, const Image& candidate, double threshold,
                            std::optional<int> channel) {
  if (!sameSize(reference, candidate))
    return {};
  // Not a structured binding: clang before 16 cannot capture those in the lambda below.
  const std::pair<int, int> range = channelRange(reference, candidate, channel);
  const int first = range.first;
  const int last = range.second;
  Image out(reference.width(), reference.height(), 1);
  parallelFor(reference.height(), [&](int y) {
    for (int x = 0; x < reference.width(); ++x) {
      bool above = false;
      for (int c = first; c < last; ++c) {
        above = above ||
                std::abs(double(reference.at(x, y, c)) - double(candidate.at(x, y, c))) > threshold;
      }
      out.at(x, y, 0) = above ? 1.0f : 0.0f;
    }
  });
  return out;
}

Image blockError(const Image& reference, const Image& candidate, int blockWidth, int blockHeight,
                 std::optional<int> channel) {
  if (!sameSize(reference, candidate) || blockWidth < 1 || blockHeight < 1)
    return {};
  const std::pair<int, int> range = channelRange(reference, candidate, channel);
  const int first = range.first;
  const int last = range.second;
  const int blocksWide = (reference.width() + blockWidth - 1) / blockWidth;
  const int blocksHigh = (reference.height() + blockHeight - 1) / blockHeight;
  Image out(blocksWide, blocksHigh, 1);
  parallelFor(blocksHigh, [&](int by) {
    for (int bx = 0; bx < blocksWide; ++bx) {
      double sum = 0.0;
      long count = 0;
      for (int y = by * blockHeight; y < std::min((by + 1) * blockHeight, reference.height());
           ++y) {
        for (int x = bx * blockWidth; x < std::min((bx + 1) * blockWidth, reference.width()); ++x) {
          for (int c = first; c < last; ++c) {
            const double d = double(reference.at(x, y, c)) - double(candidate.at(x, y, c));
            sum += d * d;
            ++count;
          }
        }
      }
      out.at(bx, by, 0) = count ? float(std::sqrt(sum / double(count))) : 0.0f;
    }
  });
  return out;
}

}  // namespace relief::core::inline compression
