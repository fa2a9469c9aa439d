// CompressionChooser; see CompressionChooser.h.
#include "renderer/CompressionChooser.h"

#include "core/compression/BlockRdo.h"
#include "core/compression/CompressionJob.h"
#include "core/compression/TextureFile.h"
#include "renderer/OffscreenRenderer.h"

#include <algorithm>
#include <functional>
#include <future>
#include <numeric>

namespace relief::renderer {
namespace {

// Whole combinations rendered together: for a budget the best few by the summed estimate
// (which ranks well but not exactly, since errors overlap); for a target, the cheapest ones the
// hopeful bound allows, before settling for the cheapest the pessimistic sum promises. Each is
// one render of the three views (ChooserRequest::width x height).
constexpr std::size_t kBudgetRenders = 4;
constexpr std::size_t kTargetRenders = 6;

// For a budget, candidates are screened at `fast` and only the chosen ones compressed again at
// the quality asked for: the formats differ from each other far more than one format's `fast` from
// its `normal`, and ASTC's medium preset costs 3.5 times its fast one (astcenc 4.2, 2048^2). The
// files written and every number reported for the choice are the shipped ones, measured again.
// On the 2048^2 four-map photo material (tools/bench-chooser), mobile, 6 MB: 86-88 s with every
// candidate at normal, 61-65 s screened (with Zstandard in the background); the same choice,
// 5.77 MB, rendered FLIP 0.0211. Compressing the next candidate while rendering this one was
// slower (71-75 s): the encoders already keep both cores busy.
constexpr core::CompressionQuality kScreeningQuality = core::CompressionQuality::Fast;

core::CompressionSettings candidateSettings(const ChooserRequest& request, core::MapSlot slot,
                                            core::TextureFormat format) {
  core::CompressionSettings settings;
  if (const auto& preset = request.presetChoices[std::size_t(slot)])
    settings = *preset;
  settings.format = format;
  settings.quality = request.quality;
  settings.mipmaps = true;
  settings.zstdLevel = request.zstdLevel;
  settings.alphaCoverage = slot == core::MapSlot::Color ? settings.alphaCoverage : 0.0f;
  return settings;
}

core::Result<core::Material> withCompressed(
    core::Material material, core::MapSlot slot,
    std::shared_ptr<const core::CompressedTexture> texture) {
  core::Result<core::Image> decoded = core::decodeAsMap(*texture);
  if (!decoded)
    return core::makeError(decoded.error());
  material.setCompressedMap(slot, std::move(texture),
                            std::make_shared<const core::Image>(std::move(decoded).value()));
  return material;
}

// Compresses `slot` of `material` with `settings` (the ones the candidate ships with).
core::Result<std::shared_ptr<const core::CompressedTexture>> compressCandidate(
    const core::Material& material, core::MapSlot slot, const core::CompressionSettings& settings) {
  core::CompressionJob job;
  job.map = material.map(slot).image;
  job.slot = slot;
  job.settings = settings;
  job.measure = false;
  job.spreadNormals = material.map(core::MapSlot::Normal).image;
  core::Result<core::CompressionOutcome> outcome = core::runCompressionJob(job);
  if (!outcome) {
    return core::makeError("the " + std::string(core::mapSlotName(slot)) + " map in " +
                           std::string(core::textureFormatInfo(settings.format).name) + ": " +
                           outcome.error());
  }
  return outcome->texture;
}

// The KTX2 file of `texture` on a thread of its own: Zstandard at the levels the chooser counts
// (19 by default) runs on one core for a level this size, so it overlaps the next candidate's
// compression and render instead of waiting for them.
std::future<std::vector<std::uint8_t>> fileInBackground(
    std::shared_ptr<const core::CompressedTexture> texture, int zstdLevel) {
  return std::async(std::launch::async, [texture = std::move(texture), zstdLevel] {
    return core::encodeKtx2(*texture, zstdLevel);
  });
}

using MeasureAlone = std::function<core::Status(core::MapSlot slot, ChooserCandidate& candidate)>;
using RenderTogether =
    std::function<core::Result<std::vector<RenderedErrorRow>>(const core::ChooserPick& pick)>;

bool meetsTarget(const core::ChooserGoal& goal, const std::vector<RenderedErrorRow>& rows) {
  return goal.kind == core::ChooserGoalKind::Flip ? meanFlip(rows) <= goal.value
                                                  : meanPsnr(rows) >= goal.value;
}

// The chosen candidates (screened at kScreeningQuality) compressed again at request.quality, their
// files written and each measured alone and all together, in `result` and in `measured` (whose
// options the pick's estimates come from). A map whose file grew past a budget goes back to its
// screened file (the largest growth first: the screened ones met the budget); if the shipped
// quality misses a target the screened files met, all go back. What is reported is then what is
// written.
core::Status shipChosenAtQuality(const core::Material& material, const ChooserRequest& request,
                                 const MeasureAlone& measureAlone,
                                 const RenderTogether& renderTogether,
                                 std::vector<core::ChooserMap>& measured, ChooserResult& result) {
  const std::vector<std::size_t> options = result.pick->options;
  const std::size_t maps = result.maps.size();
  const auto chosen = [&](std::size_t m) -> ChooserCandidate& {
    return result.maps[m].candidates[options[m]];
  };
  std::vector<ChooserCandidate> screened(maps);
  std::vector<std::future<std::vector<std::uint8_t>>> files(maps);
  for (std::size_t m = 0; m < maps; ++m) {
    ChooserCandidate& candidate = chosen(m);
    screened[m] = candidate;
    candidate.settings.quality = request.quality;
    core::Result<std::shared_ptr<const core::CompressedTexture>> texture =
        compressCandidate(material, result.maps[m].slot, candidate.settings);
    if (!texture)
      return core::makeError(texture.error());
    candidate.texture = std::move(texture).value();
    files[m] = fileInBackground(candidate.texture, request.zstdLevel);
    if (core::Status alone = measureAlone(result.maps[m].slot, candidate); !alone)
      return alone;
  }
  std::uint64_t total = 0;
  for (std::size_t m = 0; m < maps; ++m) {
    chosen(m).file = files[m].get();
    chosen(m).option.bytes = chosen(m).file.size();
    total += chosen(m).option.bytes;
  }
  const auto revert = [&](std::size_t m) {
    total = total - chosen(m).option.bytes + screened[m].option.bytes;
    chosen(m) = screened[m];
  };
  const core::ChooserGoal& goal = request.goal;
  if (goal.kind == core::ChooserGoalKind::Budget && double(total) > goal.value) {
    std::vector<std::size_t> byGrowth(maps);
    std::iota(byGrowth.begin(), byGrowth.end(), std::size_t(0));
    const auto growth = [&](std::size_t m) {
      return double(chosen(m).option.bytes) - double(screened[m].option.bytes);
    };
    std::sort(byGrowth.begin(), byGrowth.end(),
              [&](std::size_t a, std::size_t b) { return growth(a) > growth(b); });
    for (std::size_t m : byGrowth) {
      if (double(total) <= goal.value)
        break;
      revert(m);
    }
  }
  const auto estimate = [&] {
    for (std::size_t m = 0; m < maps; ++m)
      measured[m].options[options[m]] = chosen(m).option;
    *result.pick = core::estimatePick(measured, options);
  };
  estimate();
  core::Result<std::vector<RenderedErrorRow>> rows = renderTogether(*result.pick);
  if (!rows)
    return core::makeError(rows.error());
  if (goal.kind != core::ChooserGoalKind::Budget && !meetsTarget(goal, rows.value())) {
    for (std::size_t m = 0; m < maps; ++m)
      revert(m);
    estimate();
    return {};  // result.measured is still the screened files' measurement
  }
  result.measured = std::move(rows).value();
  result.measuredFlip = meanFlip(result.measured);
  result.measuredPsnr = meanPsnr(result.measured);
  return {};
}

}  // namespace

double meanFlip(const std::vector<RenderedErrorRow>& rows) {
  double sum = 0.0;
  for (const RenderedErrorRow& row : rows)
    sum += row.flipMean;
  return rows.empty() ? 0.0 : sum / double(rows.size());
}

double meanPsnr(const std::vector<RenderedErrorRow>& rows) {
  double sum = 0.0;
  for (const RenderedErrorRow& row : rows)
    sum += row.mse;
  return core::psnrFromMse(rows.empty() ? 0.0 : sum / double(rows.size()));
}

std::vector<const ChooserCandidate*> ChooserResult::chosen() const {
  std::vector<const ChooserCandidate*> picks(maps.size(), nullptr);
  if (!pick)
    return picks;
  for (std::size_t m = 0; m < maps.size(); ++m)
    picks[m] = &maps[m].candidates[pick->options[m]];
  return picks;
}

core::Result<ChooserResult> chooseCompression(OffscreenRenderer& offscreen,
                                              const core::Material& material,
                                              const FrameSettings& frame,
                                              const ChooserRequest& request,
                                              const core::WorkControl& control) {
  ChooserResult result;
  FrameSettings shipped = frame;
  std::size_t candidateCount = 0;
  for (core::MapSlot slot : core::kAllMapSlots) {
    const core::Image* map = material.image(slot);
    if (!map)
      continue;
    ChooserMapResult entry;
    entry.slot = slot;
    for (core::TextureFormat format :
         core::chooserFormats(slot, map->channels(), request.platform)) {
      for (float lambda : core::chooserRdoLambdas(request.platform)) {
        if (lambda > 0.0f && !core::formatHasRdo(format))
          continue;
        ChooserCandidate candidate;
        candidate.option.format = format;
        candidate.option.rdoLambda = lambda;
        candidate.settings = candidateSettings(request, slot, format);
        candidate.settings.rdoLambda = lambda;
        entry.candidates.push_back(std::move(candidate));
      }
    }
    // The original is drawn with the chain the candidates ship with, so that both differ by
    // the compression alone.
    shipped.mipChains[std::size_t(slot)] = core::shippedMipChain(entry.candidates[0].settings);
    candidateCount += entry.candidates.size();
    result.maps.push_back(std::move(entry));
  }
  if (result.maps.empty())
    return core::makeError("the material has no maps to compress");

  // One step a candidate (compress, write, render), the original, and about four renders of
  // whole combinations.
  const double steps = double(candidateCount + 5);
  double done = 0.0;
  offscreen.setMaterial(material);
  core::Result<RenderedViews> original =
      renderErrorViews(offscreen, material, shipped, request.width, request.height);
  if (!original)
    return core::makeError(original.error());
  control.report(++done / steps);

  // Each candidate compressed at the screening quality, measured alone; its file is written in
  // the background meanwhile.
  // A quality target is judged on the errors themselves, which a faster encoder overstates (it
  // found no combination for a FLIP target the normal files meet), so targets are measured at
  // the quality asked for; a budget is judged on bytes, and the errors only rank.
  const core::CompressionQuality screening = request.goal.kind == core::ChooserGoalKind::Budget
                                                 ? std::min(kScreeningQuality, request.quality)
                                                 : request.quality;
  std::vector<std::vector<std::future<std::vector<std::uint8_t>>>> files(result.maps.size());
  const auto measureAlone = [&](core::MapSlot slot, ChooserCandidate& candidate) -> core::Status {
    core::Result<core::Material> compressed = withCompressed(material, slot, candidate.texture);
    if (!compressed)
      return core::makeError(compressed.error());
    core::Result<RenderedViews> views =
        renderErrorViews(offscreen, compressed.value(), shipped, request.width, request.height);
    if (!views)
      return core::makeError(views.error());
    candidate.rows = compareRenderedViews(original.value(), views.value());
    candidate.option.flip = meanFlip(candidate.rows);
    candidate.option.mse = 0.0;
    for (const RenderedErrorRow& row : candidate.rows)
      candidate.option.mse += row.mse / double(candidate.rows.size());
    return {};
  };
  for (std::size_t m = 0; m < result.maps.size(); ++m) {
    ChooserMapResult& entry = result.maps[m];
    for (ChooserCandidate& candidate : entry.candidates) {
      if (control.cancelled())
        return core::makeError("cancelled");
      candidate.settings.quality = screening;
      core::Result<std::shared_ptr<const core::CompressedTexture>> texture =
          compressCandidate(material, entry.slot, candidate.settings);
      if (!texture)
        return core::makeError(texture.error());
      candidate.texture = std::move(texture).value();
      files[m].push_back(fileInBackground(candidate.texture, request.zstdLevel));
      if (core::Status alone = measureAlone(entry.slot, candidate); !alone)
        return core::makeError(alone.error());
      control.report(++done / steps);
    }
  }
  std::vector<core::ChooserMap> measured;
  for (std::size_t m = 0; m < result.maps.size(); ++m) {
    core::ChooserMap chooserMap{result.maps[m].slot, {}};
    for (std::size_t c = 0; c < result.maps[m].candidates.size(); ++c) {
      ChooserCandidate& candidate = result.maps[m].candidates[c];
      candidate.file = files[m][c].get();
      candidate.option.bytes = candidate.file.size();
      chooserMap.options.push_back(candidate.option);
    }
    measured.push_back(std::move(chooserMap));
  }

  // Render the combinations that matter together; the measurement decides.
  const auto renderTogether =
      [&](const core::ChooserPick& pick) -> core::Result<std::vector<RenderedErrorRow>> {
    core::Material together = material;
    for (std::size_t m = 0; m < result.maps.size(); ++m) {
      const ChooserCandidate& candidate = result.maps[m].candidates[pick.options[m]];
      core::Result<core::Material> next =
          withCompressed(std::move(together), result.maps[m].slot, candidate.texture);
      if (!next)
        return core::makeError(next.error());
      together = std::move(next).value();
    }
    core::Result<RenderedViews> views =
        renderErrorViews(offscreen, together, shipped, request.width, request.height);
    if (!views)
      return core::makeError(views.error());
    ++result.combinationsMeasured;
    control.report(std::min(++done, steps - 1.0) / steps);
    return compareRenderedViews(original.value(), views.value());
  };
  const auto keep = [&](const core::ChooserPick& pick, std::vector<RenderedErrorRow> rows) {
    result.pick = pick;
    result.measuredFlip = meanFlip(rows);
    result.measuredPsnr = meanPsnr(rows);
    result.measured = std::move(rows);
  };
  const core::ChooserGoal& goal = request.goal;
  result.closest = core::closestPick(measured, goal);
  const std::vector<core::ChooserPick> ranked = core::rankPicks(measured, goal);
  if (goal.kind == core::ChooserGoalKind::Budget) {
    for (std::size_t i = 0; i < std::min(ranked.size(), kBudgetRenders); ++i) {
      core::Result<std::vector<RenderedErrorRow>> rows = renderTogether(ranked[i]);
      if (!rows)
        return core::makeError(rows.error());
      if (!result.pick || meanFlip(rows.value()) < result.measuredFlip)
        keep(ranked[i], std::move(rows).value());
    }
  } else {
    // The cheapest few the hopeful bound allows, then the cheapest the sum promises.
    std::vector<const core::ChooserPick*> tries;
    for (std::size_t i = 0; i < std::min(ranked.size(), kTargetRenders); ++i)
      tries.push_back(&ranked[i]);
    for (std::size_t i = kTargetRenders; i < ranked.size(); ++i) {
      if (core::estimateMeets(ranked[i], goal)) {
        tries.push_back(&ranked[i]);
        break;
      }
    }
    for (const core::ChooserPick* pick : tries) {
      if (control.cancelled())
        return core::makeError("cancelled");
      core::Result<std::vector<RenderedErrorRow>> rows = renderTogether(*pick);
      if (!rows)
        return core::makeError(rows.error());
      if (meetsTarget(goal, rows.value())) {
        keep(*pick, std::move(rows).value());
        break;
      }
    }
  }
  if (result.pick && screening != request.quality) {
    if (core::Status shippedAtQuality =
            shipChosenAtQuality(material, request, measureAlone, renderTogether, measured, result);
        !shippedAtQuality)
      return core::makeError(shippedAtQuality.error());
  }
  control.report(1.0);
  offscreen.setMaterial(material);
  return result;
}

}  // namespace relief::renderer
