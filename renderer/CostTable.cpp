// CostTable; see CostTable.h.
#include "renderer/CostTable.h"

#include "core/tracing/UvErrorMap.h"
#include "renderer/MaterialRenderer.h"

#include <cstdio>

namespace relief::renderer {
namespace {

struct RowSpec {
  core::Technique technique;
  int minSamples = 0;  // 0: the material's own counts
  int maxSamples = 0;
};

// POM at three counts, lerped by the view angle alone (as engines count them), beside every
// other technique at the material's own settings.
constexpr RowSpec kRows[] = {
    {core::Technique::Normal},       {core::Technique::Parallax},
    {core::Technique::Pom, 8, 32},   {core::Technique::Pom, 16, 64},
    {core::Technique::Pom, 32, 128}, {core::Technique::Relief},
    {core::Technique::Cone},         {core::Technique::Quadtree},
    {core::Technique::Displacement},
};

core::Material rowMaterial(const core::Material& base, const RowSpec& spec, std::string& label) {
  core::Material material = base;
  material.setTechnique(spec.technique);
  label = std::string(core::techniqueName(spec.technique));
  if (spec.minSamples > 0) {
    material.setParameter(core::ParamId::MinSamples, spec.minSamples);
    material.setParameter(core::ParamId::MaxSamples, spec.maxSamples);
    material.setParameter(core::ParamId::SamplesPerTexel, 0.0);
    label += " " + std::to_string(spec.minSamples) + "-" + std::to_string(spec.maxSamples);
  }
  return material;
}

}  // namespace

core::Result<CostTable> measureCostTableFrames(MaterialRenderer& renderer,
                                               const FrameSettings& frame, int width, int height,
                                               const FrameTiming& timing) {
  const core::Material base = renderer.material();
  FrameSettings pass = frame;
  pass.split.reset();
  pass.engine.reset();
  pass.debugView = core::DebugView::Shading;
  pass.output = FrameOutput::Display;
  FrameSettings uvPass = pass;
  uvPass.debugView = core::DebugView::Uv;
  uvPass.output = FrameOutput::FloatData;

  CostTable table;
  table.field = core::HeightField::fromMaterial(base);
  const auto fail = [&](const std::string& error) {
    renderer.setMaterial(base);
    return core::makeError(error);
  };
  for (const RowSpec& spec : kRows) {
    CostTableRow row;
    row.material = rowMaterial(base, spec, row.label);
    renderer.setMaterial(row.material);
    core::Result<FrameTimes> times = renderer.timeFrames(pass, width, height, timing);
    if (!times)
      return fail(times.error());
    row.times = times.value();
    core::Result<core::Image> finalUv = renderer.renderToImage(uvPass, width, height);
    if (!finalUv)
      return fail(finalUv.error());
    row.finalUv = std::move(finalUv).value();
    table.rows.push_back(std::move(row));
  }
  FrameSettings rayPass = uvPass;
  rayPass.output = FrameOutput::EyeRays;
  renderer.setMaterial(base);
  core::Result<core::Image> eyeRays = renderer.renderToImage(rayPass, width, height);
  if (!eyeRays)
    return fail(eyeRays.error());
  table.eyeRays = std::move(eyeRays).value();
  return table;
}

void measureCostTableErrors(CostTable& table, const std::atomic<bool>* cancel) {
  if (table.rows.empty())
    return;
  // One exact trace for every row: the eye rays do not depend on the technique. The normal
  // row's frame says which pixels are covered and where the map is minified.
  const core::Image exact =
      core::traceExactUvs(table.rows.front().finalUv, table.eyeRays, table.field, {}, cancel);
  if (cancel && cancel->load())
    return;
  for (CostTableRow& row : table.rows) {
    const core::UvErrorMap error = core::uvErrorAgainst(row.finalUv, table.eyeRays, exact,
                                                        table.field.width(), table.field.height());
    row.meanError = error.mean;
    row.p95Error = error.p95;
    row.pixels = error.pixels;
    row.finalUv = core::Image();
  }
}

std::optional<std::size_t> cheapestWithin(const CostTable& table, double maxMeanTexels) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const CostTableRow& row = table.rows[i];
    if (row.pixels == 0 || row.meanError > maxMeanTexels)
      continue;
    if (!best || row.times.fastest < table.rows[*best].times.fastest)
      best = i;
  }
  return best;
}

std::string describeCostTable(const CostTable& table, double maxMeanTexels) {
  const std::optional<std::size_t> best = cheapestWithin(table, maxMeanTexels);
  std::string text =
      "  technique        frame ms (fastest, median)   UV error texels (mean, p95)\n";
  char line[160];
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const CostTableRow& row = table.rows[i];
    std::snprintf(line, sizeof(line), "%c %-16s %8.2f %8.2f               %8.3f %8.3f\n",
                  best == i ? '*' : ' ', row.label.c_str(), row.times.fastest, row.times.median,
                  row.meanError, row.p95Error);
    text += line;
  }
  std::snprintf(line, sizeof(line), "* the cheapest within a mean error of %.3g texels%s\n",
                maxMeanTexels, best ? "" : ": none");
  text += line;
  if (!table.rows.empty() && table.rows.front().pixels == 0)
    text += "no pixel compared: the height map is minified everywhere in this view; move closer\n";
  return text;
}

}  // namespace relief::renderer
