// FrameTimes; see FrameTimes.h.
#include "renderer/FrameTimes.h"

#include <algorithm>
#include <cmath>

namespace relief::renderer {

FrameTimes summarizeFrameTimes(std::vector<double> milliseconds) {
  FrameTimes times;
  if (milliseconds.empty())
    return times;
  std::sort(milliseconds.begin(), milliseconds.end());
  const std::size_t count = milliseconds.size();
  times.frames = int(count);
  times.fastest = milliseconds.front();
  times.median = count % 2 == 1 ? milliseconds[count / 2]
                                : 0.5 * (milliseconds[count / 2 - 1] + milliseconds[count / 2]);
  // Nearest rank: the smallest value with at least 90% of the frames at or below it.
  const std::size_t rank = std::size_t(std::ceil(0.9 * double(count)));
  times.p90 = milliseconds[std::max<std::size_t>(rank, 1) - 1];
  return times;
}

}  // namespace relief::renderer
