// "Choose for me": the formats for every map of a material that meet a size budget (bytes of all
// maps as shipped: KTX2 supercompressed with Zstandard) or a rendered quality target (FLIP or
// PSNR of the lit, parallax-mapped material), with the fewest bytes or the least error. Each
// map's candidates (core FormatChooser.h) are compressed with the mip chain they ship with,
// measured by their file size and by the rendered error each makes alone (RenderedError.h's
// views) and ranked by core::rankPicks; the few combinations that matter are then rendered with
// all their maps compressed together, and the measured error decides: for a budget the least
// FLIP of the first kBudgetRenders ranked, for a target the fewest bytes that meet it. For a
// budget the candidates are screened at `fast`; the chosen ones are compressed again at the
// quality asked for and measured again, so the files and numbers of the choice are those shipped.
// `relief-cli compress --preset P --budget 6MB` and the Compress panel's Choose for Me run it.
#pragma once

#include "core/base/Result.h"
#include "core/base/WorkControl.h"
#include "core/compression/Compressor.h"
#include "core/compression/FormatChooser.h"
#include "core/material/Material.h"
#include "renderer/FrameSettings.h"
#include "renderer/RenderedError.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace relief::renderer {

class OffscreenRenderer;

struct ChooserRequest {
  core::ChooserGoal goal;
  core::ChooserPlatform platform = core::ChooserPlatform::Desktop;
  core::CompressionQuality quality = core::CompressionQuality::Normal;  // of the files shipped
  int zstdLevel = 19;  // the supercompression the sizes are counted after (1..22)
  // The preset's own choices: their mip filter, roughness fold and alpha cutoff are kept (only
  // the format is chosen); slots without one get a full box-filtered chain.
  std::array<std::optional<core::CompressionSettings>, core::kMapSlotCount> presetChoices{};
  int width = 320;  // the rendered views' size
  int height = 240;
};

struct ChooserCandidate {
  core::ChooserOption option;  // format, RDO trade, bytes, error alone
  core::CompressionSettings settings;
  std::shared_ptr<const core::CompressedTexture> texture;
  std::vector<std::uint8_t> file;      // the KTX2 file, supercompressed
  std::vector<RenderedErrorRow> rows;  // the material with this map alone compressed
};

struct ChooserMapResult {
  core::MapSlot slot = core::MapSlot::Color;
  std::vector<ChooserCandidate> candidates;
};

struct ChooserResult {
  std::vector<ChooserMapResult> maps;  // every map of the material, in slot order
  // The chosen combination (with its estimates), or none when no combination meets the goal;
  // then `closest` says what comes closest (core::closestPick).
  std::optional<core::ChooserPick> pick;
  core::ChooserPick closest;
  // The pick rendered with all its maps compressed at once (empty when nothing meets the goal).
  std::vector<RenderedErrorRow> measured;
  double measuredFlip = 0.0;     // mean over the views
  double measuredPsnr = 0.0;     // from the mean squared error over the views
  int combinationsMeasured = 0;  // whole combinations rendered together

  // The chosen candidate of each map (nullptr entries when nothing was chosen).
  std::vector<const ChooserCandidate*> chosen() const;
};

// `frame` gives the camera's yaw and distance, the light, environment and tile preview (its mip
// chains are replaced by the candidates'); the offscreen renderer's mesh must be set. Fails
// when a map cannot be compressed or a render fails; "cancelled" when cancelled. A goal no
// combination meets is not a failure: verdict.pick is empty and verdict.closest says what is.
core::Result<ChooserResult> chooseCompression(OffscreenRenderer& offscreen,
                                              const core::Material& material,
                                              const FrameSettings& frame,
                                              const ChooserRequest& request,
                                              const core::WorkControl& control = {});

// The mean FLIP and the PSNR of the mean squared error over a measurement's views.
double meanFlip(const std::vector<RenderedErrorRow>& rows);
double meanPsnr(const std::vector<RenderedErrorRow>& rows);

}  // namespace relief::renderer
