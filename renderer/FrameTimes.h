// FrameTimes: how long a frame takes, summarised from many timed frames so that a shared,
// noisy machine can still rank techniques. Other processes only ever add time to a frame, so
// the fastest frame is the steadiest figure from run to run; the median is the typical one,
// and the spread says how far to trust either.
#pragma once

#include <vector>

namespace relief::renderer {

struct FrameTiming {
  int minFrames = 10;       // timed frames at the least
  double minSeconds = 1.0;  // and frames until this much time has passed,
  int maxFrames = 200;      // but never more than this many
};

struct FrameTimes {
  double median = 0.0;   // milliseconds
  double fastest = 0.0;  // milliseconds
  double p90 = 0.0;      // milliseconds, the 90th percentile (nearest rank)
  int frames = 0;
  // (p90 - fastest) / median: 0 on a quiet machine, large when other work disturbed the run.
  double spread() const { return median > 0.0 ? (p90 - fastest) / median : 0.0; }
};

// The summary of `milliseconds` (one entry a frame; empty gives all zeros).
FrameTimes summarizeFrameTimes(std::vector<double> milliseconds);

}  // namespace relief::renderer
