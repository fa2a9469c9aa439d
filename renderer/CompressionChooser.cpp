// CompressionChooser; see CompressionChooser.h.
#include "renderer/CompressionChooser.h"

#include "core/compression/BlockRdo.h"
#include "core/compression/CompressionJob.h"
#include "core/compression/TextureFile.h"
#include "renderer/OffscreenRenderer.h"

namespace relief::renderer {
namespace {

// Whole combinations rendered together: for a budget the best few by the summed estimate
// (which ranks well but not exactly, since errors overlap); for a target, the cheapest ones the
// hopeful bound allows, before settling for the cheapest the pessimistic sum promises. Each is
// one render of the three views (ChooserRequest::width x height).
constexpr std::size_t kBudgetRenders = 4;
constexpr std::size_t kTargetRenders = 6;

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

  std::vector<core::ChooserMap> measured;
  for (ChooserMapResult& entry : result.maps) {
    core::ChooserMap chooserMap{entry.slot, {}};
    for (ChooserCandidate& candidate : entry.candidates) {
      if (control.cancelled())
        return core::makeError("cancelled");
      core::CompressionJob job;
      job.map = material.map(entry.slot).image;
      job.slot = entry.slot;
      job.settings = candidate.settings;
      job.measure = false;
      job.spreadNormals = material.map(core::MapSlot::Normal).image;
      core::Result<core::CompressionOutcome> outcome = core::runCompressionJob(job);
      if (!outcome) {
        return core::makeError("the " + std::string(core::mapSlotName(entry.slot)) + " map in " +
                               std::string(core::textureFormatInfo(candidate.option.format).name) +
                               ": " + outcome.error());
      }
      candidate.texture = outcome->texture;
      candidate.file = core::encodeKtx2(*candidate.texture, request.zstdLevel);
      candidate.option.bytes = candidate.file.size();
      core::Result<core::Material> compressed =
          withCompressed(material, entry.slot, candidate.texture);
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
      chooserMap.options.push_back(candidate.option);
      control.report(++done / steps);
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
    const auto meets = [&](const std::vector<RenderedErrorRow>& rows) {
      return goal.kind == core::ChooserGoalKind::Flip ? meanFlip(rows) <= goal.value
                                                      : meanPsnr(rows) >= goal.value;
    };
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
      if (meets(rows.value())) {
        keep(*pick, std::move(rows).value());
        break;
      }
    }
  }
  control.report(1.0);
  offscreen.setMaterial(material);
  return result;
}

}  // namespace relief::renderer
