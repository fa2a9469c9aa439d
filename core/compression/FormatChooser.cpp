// FormatChooser; see FormatChooser.h.
#include "core/compression/FormatChooser.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace relief::core::inline compression {
namespace {

// Every combination, counting through the maps' options like an odometer.
template <class Visit>
void forEachCombination(const std::vector<ChooserMap>& maps, Visit visit) {
  std::vector<std::size_t> options(maps.size(), 0);
  while (true) {
    visit(options);
    std::size_t m = 0;
    while (m < maps.size() && ++options[m] == maps[m].options.size())
      options[m++] = 0;
    if (m == maps.size())
      return;
  }
}

}  // namespace

std::string_view chooserPlatformName(ChooserPlatform platform) {
  return platform == ChooserPlatform::Desktop ? "desktop" : "mobile";
}

std::optional<ChooserPlatform> findChooserPlatform(std::string_view name) {
  for (ChooserPlatform platform : {ChooserPlatform::Desktop, ChooserPlatform::Mobile}) {
    if (chooserPlatformName(platform) == name)
      return platform;
  }
  return std::nullopt;
}

std::vector<TextureFormat> chooserFormats(MapSlot slot, int channels, ChooserPlatform platform) {
  using enum TextureFormat;
  const bool alpha = channels == 4;
  switch (mapSlotTexels(slot)) {
    case MapTexels::Colour:
      if (platform == ChooserPlatform::Desktop)
        return alpha ? std::vector{Bc3, Bc7} : std::vector{Bc1, Bc7};
      return {Astc8x8, Astc6x6, alpha ? Etc2A : Etc2, Astc4x4};
    case MapTexels::Normal:
      if (platform == ChooserPlatform::Desktop)
        return {Bc1, Bc5, Bc7};
      return {Astc8x8Normal, Astc6x6Normal, EacRg11, Astc4x4Normal};
    case MapTexels::Scalar:
      if (platform == ChooserPlatform::Desktop)
        return {Bc4};
      return {Astc8x8, Astc6x6, EacR11, Astc4x4};
  }
  return {};  // not reached: every kind is handled above
}

std::vector<float> chooserRdoLambdas(ChooserPlatform platform) {
  if (platform == ChooserPlatform::Desktop)
    return {0.0f, 16.0f};
  return {0.0f};
}

double psnrFromMse(double mse) {
  return mse > 0.0 ? -10.0 * std::log10(mse) : std::numeric_limits<double>::infinity();
}

ChooserPick estimatePick(const std::vector<ChooserMap>& maps, std::vector<std::size_t> options) {
  ChooserPick pick;
  double mse = 0.0, largestMse = 0.0;
  for (std::size_t m = 0; m < maps.size(); ++m) {
    const ChooserOption& option = maps[m].options[options[m]];
    pick.bytes += option.bytes;
    pick.flip += option.flip;
    pick.flipFloor = std::max(pick.flipFloor, option.flip);
    mse += option.mse;
    largestMse = std::max(largestMse, option.mse);
  }
  pick.psnr = psnrFromMse(mse);
  pick.psnrCeiling = psnrFromMse(largestMse);
  pick.options = std::move(options);
  return pick;
}

bool estimateMeets(const ChooserPick& pick, const ChooserGoal& goal) {
  switch (goal.kind) {
    case ChooserGoalKind::Budget:
      return double(pick.bytes) <= goal.value;
    case ChooserGoalKind::Flip:
      return pick.flip <= goal.value;
    case ChooserGoalKind::Psnr:
      return pick.psnr >= goal.value;
  }
  return false;  // not reached: every kind is handled above
}

std::vector<ChooserPick> rankPicks(const std::vector<ChooserMap>& maps, const ChooserGoal& goal) {
  std::vector<ChooserPick> picks;
  forEachCombination(maps, [&](const std::vector<std::size_t>& options) {
    ChooserPick pick = estimatePick(maps, options);
    const bool possible = goal.kind == ChooserGoalKind::Budget ? double(pick.bytes) <= goal.value
                          : goal.kind == ChooserGoalKind::Flip ? pick.flipFloor <= goal.value
                                                               : pick.psnrCeiling >= goal.value;
    if (possible)
      picks.push_back(std::move(pick));
  });
  const auto order = [&](const ChooserPick& a, const ChooserPick& b) {
    if (goal.kind == ChooserGoalKind::Budget) {
      if (a.flip != b.flip)
        return a.flip < b.flip;
      return a.bytes < b.bytes;
    }
    if (a.bytes != b.bytes)
      return a.bytes < b.bytes;
    return goal.kind == ChooserGoalKind::Flip ? a.flip < b.flip : a.psnr > b.psnr;
  };
  std::stable_sort(picks.begin(), picks.end(), order);
  return picks;
}

ChooserPick closestPick(const std::vector<ChooserMap>& maps, const ChooserGoal& goal) {
  std::optional<ChooserPick> closest;
  forEachCombination(maps, [&](const std::vector<std::size_t>& options) {
    ChooserPick pick = estimatePick(maps, options);
    const bool closer =
        !closest || (goal.kind == ChooserGoalKind::Budget ? pick.bytes < closest->bytes
                     : goal.kind == ChooserGoalKind::Flip ? pick.flip < closest->flip
                                                          : pick.psnr > closest->psnr);
    if (closer)
      closest = std::move(pick);
  });
  return closest.value_or(ChooserPick{});
}

}  // namespace relief::core::inline compression
