// The chooser's search (core/compression/FormatChooser.h) on hand-made measurements, where every
// combination can be worked out by hand, and the budget sizes it reads (core/base/ByteSize.h).
#include "core/base/ByteSize.h"
#include "core/compression/Compressor.h"
#include "core/compression/FormatChooser.h"

#include <gtest/gtest.h>

#include <cmath>

namespace relief::core {
namespace {

using enum TextureFormat;

// Colour: BC1 1000 bytes FLIP 0.03, BC7 3000 bytes 0.01. Normal: BC1 1000 / 0.02, BC5 4000 /
// 0.005, BC7 3500 / 0.008. Height: BC4 2000 / 0.004.
std::vector<ChooserMap> measuredMaps() {
  return {
      {MapSlot::Color, {{Bc1, 0.0f, 1000, 0.03, 1e-3}, {Bc7, 0.0f, 3000, 0.01, 1e-4}}},
      {MapSlot::Normal,
       {{Bc1, 0.0f, 1000, 0.02, 5e-4},
        {Bc5, 0.0f, 4000, 0.005, 2e-5},
        {Bc7, 0.0f, 3500, 0.008, 4e-5}}},
      {MapSlot::Height, {{Bc4, 0.0f, 2000, 0.004, 1e-5}}},
  };
}

TEST(FormatChooser, CandidatesSuitTheirSlotAndDevice) {
  EXPECT_EQ(chooserFormats(MapSlot::Color, 3, ChooserPlatform::Desktop), (std::vector{Bc1, Bc7}));
  EXPECT_EQ(chooserFormats(MapSlot::Color, 4, ChooserPlatform::Desktop), (std::vector{Bc3, Bc7}));
  for (MapSlot slot : kAllMapSlots) {
    for (ChooserPlatform device : {ChooserPlatform::Desktop, ChooserPlatform::Mobile}) {
      for (int channels : {1, 3, 4}) {
        const std::vector<TextureFormat> formats = chooserFormats(slot, channels, device);
        ASSERT_FALSE(formats.empty());
        for (TextureFormat format : formats) {
          EXPECT_TRUE(formatSuitsSlot(format, slot)) << textureFormatInfo(format).name;
          const FormatFamily family = textureFormatInfo(format).family;
          EXPECT_EQ(family == FormatFamily::Bc, device == ChooserPlatform::Desktop)
              << textureFormatInfo(format).name;
          if (slot == MapSlot::Color && channels == 4) {
            EXPECT_NE(textureFormatInfo(format).layout, FormatLayout::Rgb)
                << textureFormatInfo(format).name << " drops the alpha";
          }
        }
      }
    }
  }
}

TEST(FormatChooser, EstimatesAreTheSumAndTheLargest) {
  const ChooserPick pick = estimatePick(measuredMaps(), {1, 0, 0});  // BC7, BC1 normal, BC4
  EXPECT_EQ(pick.bytes, 6000u);
  EXPECT_DOUBLE_EQ(pick.flip, 0.01 + 0.02 + 0.004);
  EXPECT_DOUBLE_EQ(pick.flipFloor, 0.02);
  EXPECT_NEAR(pick.psnr, -10.0 * std::log10(1e-4 + 5e-4 + 1e-5), 1e-12);
  EXPECT_NEAR(pick.psnrCeiling, -10.0 * std::log10(5e-4), 1e-12);
  EXPECT_DOUBLE_EQ(psnrFromMse(0.01), 20.0);
  EXPECT_TRUE(std::isinf(psnrFromMse(0.0)));
}

TEST(FormatChooser, ABudgetRanksWhatFitsByError) {
  const std::vector<ChooserMap> maps = measuredMaps();
  // The six combinations (colour, normal; the height's BC4 in all): (bc1, bc1) 4000 bytes FLIP
  // 0.054, (bc1, bc5) 7000 0.039, (bc1, bc7) 6500 0.042, (bc7, bc1) 6000 0.034, (bc7, bc5) 9000
  // 0.019, (bc7, bc7) 8500 0.022. Within 8600 bytes all but (bc7, bc5), least FLIP first.
  const ChooserGoal budget{ChooserGoalKind::Budget, 8600.0};
  const std::vector<ChooserPick> ranked = rankPicks(maps, budget);
  ASSERT_EQ(ranked.size(), 5u);
  for (const ChooserPick& pick : ranked)
    EXPECT_LE(double(pick.bytes), budget.value);
  const std::vector<std::vector<std::size_t>> order = {
      {1, 2, 0}, {1, 0, 0}, {0, 1, 0}, {0, 2, 0}, {0, 0, 0}};
  for (std::size_t i = 0; i < order.size(); ++i)
    EXPECT_EQ(ranked[i].options, order[i]) << i;
  EXPECT_NEAR(ranked[0].flip, 0.022, 1e-12);
  // Within 6200: (bc7, bc1) then (bc1, bc1).
  const std::vector<ChooserPick> tight = rankPicks(maps, {ChooserGoalKind::Budget, 6200.0});
  ASSERT_EQ(tight.size(), 2u);
  EXPECT_EQ(tight[0].bytes, 6000u);
  EXPECT_EQ(tight[1].bytes, 4000u);
  // Closest when it cannot be met: the smallest combination, 4000 bytes.
  EXPECT_TRUE(rankPicks(maps, {ChooserGoalKind::Budget, 3999.0}).empty());
  const ChooserPick smallest = closestPick(maps, {ChooserGoalKind::Budget, 3999.0});
  EXPECT_EQ(smallest.bytes, 4000u);
  EXPECT_EQ(smallest.options, (std::vector<std::size_t>{0, 0, 0}));
}

TEST(FormatChooser, ATargetRanksWhatMightReachItBySize) {
  const std::vector<ChooserMap> maps = measuredMaps();
  // FLIP 0.025: the hopeful bound (largest map alone) rules out every combination with colour
  // BC1 (0.03); with colour BC7 all three normals might do: 6000, 8500, 9000 bytes.
  const ChooserGoal flip{ChooserGoalKind::Flip, 0.025};
  const std::vector<ChooserPick> ranked = rankPicks(maps, flip);
  ASSERT_EQ(ranked.size(), 3u);
  EXPECT_EQ(ranked[0].bytes, 6000u);
  EXPECT_EQ(ranked[1].bytes, 8500u);
  EXPECT_EQ(ranked[2].bytes, 9000u);
  for (const ChooserPick& pick : ranked)
    EXPECT_LE(pick.flipFloor, flip.value);
  // The summed estimate: (bc7, bc1) 0.034 does not promise it; (bc7, bc7) 0.022 and (bc7, bc5)
  // 0.019 do.
  EXPECT_FALSE(estimateMeets(ranked[0], flip));
  EXPECT_TRUE(estimateMeets(ranked[1], flip));
  EXPECT_TRUE(estimateMeets(ranked[2], flip));
  // Out of reach: 0.009 is below colour BC7's 0.01 alone; closest is the least summed error.
  EXPECT_TRUE(rankPicks(maps, {ChooserGoalKind::Flip, 0.009}).empty());
  EXPECT_EQ(closestPick(maps, {ChooserGoalKind::Flip, 0.009}).options,
            (std::vector<std::size_t>{1, 1, 0}));
  // PSNR: at least 33 dB needs the summed MSE under 5.0e-4; the hopeful bound, the largest under
  // it: colour BC1 (1e-3) is out, normal BC1 (5e-4) is at 33.01 dB and in.
  const std::vector<ChooserPick> psnr = rankPicks(maps, {ChooserGoalKind::Psnr, 33.0});
  ASSERT_EQ(psnr.size(), 3u);
  EXPECT_EQ(psnr[0].options, (std::vector<std::size_t>{1, 0, 0}));
}

TEST(ByteSize, BudgetsAsPeopleWriteThem) {
  EXPECT_EQ(parseByteSize("6MB"), 6000000u);
  EXPECT_EQ(parseByteSize("6 mb"), 6000000u);
  EXPECT_EQ(parseByteSize("512KiB"), 524288u);
  EXPECT_EQ(parseByteSize("1.5 GB"), 1500000000u);
  EXPECT_EQ(parseByteSize("2MiB"), 2097152u);
  EXPECT_EQ(parseByteSize("700000"), 700000u);
  EXPECT_EQ(parseByteSize("700000 bytes"), 700000u);
  for (const char* bad : {"0", "-1MB", "abc", "6 XB", "", "MB", "nan", "inf", "0.4"})
    EXPECT_FALSE(parseByteSize(bad).has_value()) << bad;
  EXPECT_EQ(describeByteSize(999), "999 bytes");
  EXPECT_EQ(describeByteSize(5870000), "5.87 MB");
  EXPECT_EQ(describeByteSize(812400), "812.4 kB");
  EXPECT_EQ(describeByteSize(1000), "1.00 kB");
}

}  // namespace
}  // namespace relief::core
