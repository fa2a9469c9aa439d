// The frame-time summary behind render --stats: median, fastest, nearest-rank 90th percentile
// and spread, worked by hand on small samples.
#include "renderer/FrameTimes.h"

#include <gtest/gtest.h>

namespace relief::renderer {
namespace {

TEST(FrameTimes, SummarisesAnOddSample) {
  // Sorted: 10 11 12 13 40. Median 12; nearest rank ceil(0.9 * 5) = 5 -> 40.
  const FrameTimes times = summarizeFrameTimes({13.0, 40.0, 10.0, 12.0, 11.0});
  EXPECT_EQ(times.frames, 5);
  EXPECT_DOUBLE_EQ(times.fastest, 10.0);
  EXPECT_DOUBLE_EQ(times.median, 12.0);
  EXPECT_DOUBLE_EQ(times.p90, 40.0);
  EXPECT_DOUBLE_EQ(times.spread(), (40.0 - 10.0) / 12.0);
}

TEST(FrameTimes, SummarisesAnEvenSample) {
  // Ten frames 1..10: median (5 + 6) / 2, nearest rank ceil(9) = 9 -> 9.
  const FrameTimes times = summarizeFrameTimes({10, 9, 8, 7, 6, 5, 4, 3, 2, 1});
  EXPECT_EQ(times.frames, 10);
  EXPECT_DOUBLE_EQ(times.median, 5.5);
  EXPECT_DOUBLE_EQ(times.fastest, 1.0);
  EXPECT_DOUBLE_EQ(times.p90, 9.0);
}

TEST(FrameTimes, OneOutlierMovesNeitherTheFastestNorTheMedian) {
  // A frame disturbed by another process: the fastest and the median hold, the p90 and the
  // spread show it once it reaches the top tenth.
  std::vector<double> quiet(20, 8.0);
  quiet[3] = 7.5;
  std::vector<double> disturbed = quiet;
  disturbed[7] = 90.0;
  const FrameTimes a = summarizeFrameTimes(quiet), b = summarizeFrameTimes(disturbed);
  EXPECT_DOUBLE_EQ(a.fastest, b.fastest);
  EXPECT_DOUBLE_EQ(a.median, b.median);
  EXPECT_DOUBLE_EQ(b.p90, 8.0);  // rank 18 of 20: still a quiet frame
  EXPECT_NEAR(a.spread(), 0.5 / 8.0, 1e-12);
}

TEST(FrameTimes, AnEmptySampleIsAllZero) {
  const FrameTimes times = summarizeFrameTimes({});
  EXPECT_EQ(times.frames, 0);
  EXPECT_EQ(times.median, 0.0);
  EXPECT_EQ(times.spread(), 0.0);
}

}  // namespace
}  // namespace relief::renderer
