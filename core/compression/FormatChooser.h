// Choosing the formats of a whole material to a budget or a quality target (issue "Judged where
// the artist looks", part 4). Each map has a few candidate formats, each measured beforehand by
// its size as shipped (KTX2 after Zstandard) and by the error it makes in the rendered material
// when it alone is compressed (renderer/CompressionChooser.h). The material's error under a
// combination lies between the largest of its maps' errors (compressing one more map rarely
// hides another's error) and their sum (errors in different pixels add; in the same pixels they
// overlap, so the sum is pessimistic: measured on the bricks sample, 0.0119 together against
// 0.0188 summed). The combinations are searched exhaustively (at most six maps of at most four
// candidates) and ranked for the renderer to measure the few that matter together.
#pragma once

#include "core/compression/TextureFormat.h"
#include "core/material/MapSlot.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace relief::core::inline compression {

// Which GPUs the files are for: desktop (BC1-BC7) or mobile (ETC2/EAC and ASTC LDR).
enum class ChooserPlatform { Desktop, Mobile };
std::string_view chooserPlatformName(ChooserPlatform platform);  // "desktop", "mobile"
std::optional<ChooserPlatform> findChooserPlatform(std::string_view name);

// The formats the chooser tries for a map of `slot` with `channels` channels (4: its alpha is
// kept), smallest first where sizes differ: desktop colour BC1 | BC7 (BC3 | BC7 with alpha),
// normals BC1 | BC5 | BC7, single values BC4; mobile ETC2 (RGBA with alpha), EAC RG11 for
// normals, EAC R11 for single values, and ASTC 8x8, 6x6 and 4x4 for every kind.
std::vector<TextureFormat> chooserFormats(MapSlot slot, int channels, ChooserPlatform platform);

// The RDO trades (BlockRdo.h) tried for each format that has RDO, 0 (off) first: desktop 0 and
// 16 (a quarter to a half smaller after Zstandard for a fraction of a dB on photographs,
// docs/compression.md); mobile formats have none.
std::vector<float> chooserRdoLambdas(ChooserPlatform platform);

// One candidate, measured: its bytes as shipped and the rendered error it alone makes.
struct ChooserOption {
  TextureFormat format = TextureFormat::Bc1;
  float rdoLambda = 0.0f;
  std::uint64_t bytes = 0;
  double flip = 0.0;  // mean FLIP of the rendered material over the measured views
  double mse = 0.0;   // mean squared error of the rendered pictures (0..1 values) over the views
};

struct ChooserMap {
  MapSlot slot = MapSlot::Color;
  std::vector<ChooserOption> options;  // at least one
};

enum class ChooserGoalKind {
  Budget,  // bytes of all maps at most `value`; the least FLIP among those
  Flip,    // rendered FLIP at most `value`; the fewest bytes among those
  Psnr,    // rendered PSNR at least `value` dB; the fewest bytes among those
};
struct ChooserGoal {
  ChooserGoalKind kind = ChooserGoalKind::Budget;
  double value = 0.0;
};

// A combination: one option index per map (in the maps' order), its bytes and the bounds of its
// error (see above).
struct ChooserPick {
  std::vector<std::size_t> options;
  std::uint64_t bytes = 0;
  double flip = 0.0;         // the maps' FLIP summed: the pessimistic estimate
  double flipFloor = 0.0;    // the largest map's FLIP: the hopeful one
  double psnr = 0.0;         // dB from the summed squared error; infinity when it is 0
  double psnrCeiling = 0.0;  // dB from the largest map's squared error
};

ChooserPick estimatePick(const std::vector<ChooserMap>& maps, std::vector<std::size_t> options);

// The combinations worth rendering, in the order to try them. A budget: those within it, least
// summed FLIP first (the renderer measures the first few and keeps the best measured). A quality
// target: those whose hopeful bound reaches it, fewest bytes first (the renderer takes the
// first that, rendered, meets it). Empty when no combination can meet the goal. Maps must each
// have an option.
std::vector<ChooserPick> rankPicks(const std::vector<ChooserMap>& maps, const ChooserGoal& goal);

// What comes closest to a goal that cannot be met: for a budget the smallest combination, for a
// target the one of least (summed) error.
ChooserPick closestPick(const std::vector<ChooserMap>& maps, const ChooserGoal& goal);

// Whether the summed (pessimistic) estimate already meets the goal; for a budget, its bytes.
bool estimateMeets(const ChooserPick& pick, const ChooserGoal& goal);

// 10 log10(1 / mse) for values in 0..1; infinity for 0.
double psnrFromMse(double mse);

}  // namespace relief::core::inline compression
