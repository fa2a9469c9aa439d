// RenderAnalysis; see RenderAnalysis.h.
#include "RenderAnalysis.h"

#include "CliCommon.h"

#include "core/compression/CompressionJob.h"
#include "core/exporters/EnginePreview.h"
#include "renderer/CompressionChooser.h"
#include "renderer/CostTable.h"
#include "renderer/EngineGrid.h"
#include "renderer/OffscreenRenderer.h"
#include "renderer/RenderedError.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QStringList>

#include <cmath>
#include <cstdio>

namespace relief::cli {

core::Result<core::Image> renderEngineGrid(renderer::OffscreenRenderer& offscreen,
                                           const renderer::FrameSettings& frame, int width,
                                           int height, bool json, QJsonObject& report) {
  auto panels = offscreen.renderEngineGridPanels(frame, width, height);
  if (!panels)
    return core::makeError(panels.error());
  renderer::EngineGrid grid = renderer::composeEngineGrid(panels.value());
  QJsonArray rows;
  for (const renderer::EngineGridPanel& panel : grid.panels) {
    rows.append(QJsonObject{
        {QStringLiteral("engine"),
         panel.engine ? qstr(core::engineInfo(*panel.engine).name) : QStringLiteral("relief")},
        {QStringLiteral("label"), QString::fromStdString(panel.label)},
        {QStringLiteral("uvErrorTexels"),
         QJsonObject{{QStringLiteral("mean"), panel.error.mean},
                     {QStringLiteral("p95"), panel.error.p95},
                     {QStringLiteral("max"), panel.error.maximum},
                     {QStringLiteral("pixels"), double(panel.error.pixels)}}}});
  }
  report.insert(QStringLiteral("panels"), rows);
  if (!json)
    printOut(QString::fromStdString(renderer::describeEngineGrid(grid)));
  return std::move(grid.picture);
}

namespace {

QJsonArray viewRows(const std::vector<renderer::RenderedErrorRow>& rows) {
  QJsonArray views;
  for (const renderer::RenderedErrorRow& row : rows) {
    views.append(QJsonObject{
        {QStringLiteral("view"), QString::fromStdString(row.view)},
        // JSON has no infinity: identical pictures have a null PSNR.
        {QStringLiteral("psnr"), std::isinf(row.psnr) ? QJsonValue() : QJsonValue(row.psnr)},
        {QStringLiteral("flip"), row.flipMean},
        {QStringLiteral("uvShiftTexels"),
         QJsonObject{{QStringLiteral("mean"), row.uvShiftMeanTexels},
                     {QStringLiteral("p95"), row.uvShiftP95Texels}}}});
  }
  return views;
}

}  // namespace

int printCompressionError(renderer::OffscreenRenderer& offscreen, const core::Material& material,
                          const std::array<core::MapCompression, core::kMapSlotCount>& compression,
                          const renderer::FrameSettings& frame, int width, int height, bool json) {
  core::Material compressed = material;
  QJsonArray maps;
  QStringList mapsText;
  for (core::MapSlot slot : core::kAllMapSlots) {
    const core::MapCompression& choice = compression[std::size_t(slot)];
    if (!choice || !material.hasMap(slot))
      continue;
    core::CompressionJob job;
    job.map = material.map(slot).image;
    job.slot = slot;
    job.settings = *choice;
    job.measure = false;
    job.spreadNormals = material.map(core::MapSlot::Normal).image;
    core::Result<core::CompressionOutcome> outcome = core::runCompressionJob(job);
    if (!outcome) {
      printError(QStringLiteral("the %1 map: %2")
                     .arg(qstr(core::mapSlotLabel(slot)).toLower(),
                          QString::fromStdString(outcome.error())));
      return kExitFailure;
    }
    core::Result<core::Image> decoded = core::decodeAsMap(*outcome->texture);
    if (!decoded) {
      printError(QString::fromStdString(decoded.error()));
      return kExitFailure;
    }
    compressed.setCompressedMap(slot, outcome->texture,
                                std::make_shared<const core::Image>(std::move(decoded).value()));
    const QString format = qstr(core::textureFormatInfo(choice->format).name);
    maps.append(QJsonObject{{QStringLiteral("slot"), qstr(core::mapSlotName(slot))},
                            {QStringLiteral("format"), format},
                            {QStringLiteral("mipmaps"), choice->mipmaps}});
    mapsText << QStringLiteral("%1 %2").arg(qstr(core::mapSlotName(slot)), format);
  }
  core::Result<std::vector<renderer::RenderedErrorRow>> rows =
      renderer::measureRenderedError(offscreen, material, compressed, frame, width, height);
  if (!rows) {
    printError(QStringLiteral("render --compression-error: ") +
               QString::fromStdString(rows.error()));
    return kExitFailure;
  }
  if (!json) {
    printOut((mapsText.isEmpty() ? QStringLiteral("no map has a compression choice: the "
                                                  "material renders as it is\n")
                                 : QStringLiteral("compressed: %1\n").arg(mapsText.join(", "))) +
             QString::fromStdString(renderer::describeRenderedError(rows.value())));
    return kExitOk;
  }
  printJson(QJsonObject{{QStringLiteral("maps"), maps},
                        {QStringLiteral("width"), width},
                        {QStringLiteral("height"), height},
                        {QStringLiteral("views"), viewRows(rows.value())}});
  return kExitOk;
}

int printCandidateErrors(renderer::OffscreenRenderer& offscreen, const core::Material& material,
                         core::MapSlot slot, const QStringList& files,
                         const renderer::FrameSettings& frame, int width, int height, bool json,
                         bool progressLines) {
  const QString slotName = qstr(core::mapSlotName(slot));
  if (!material.hasMap(slot)) {
    printError(QStringLiteral("--slot %1: the preset has no %1 map to compare with").arg(slotName));
    return kExitUsage;
  }
  // Every file is read and its size checked before anything is rendered: a bad one fails at
  // once. They are decoded one at a time below (decoded maps are 16 bytes a texel).
  const core::Image& map = *material.image(slot);
  std::vector<core::CompressedTexture> textures;
  for (const QString& file : files) {
    core::Result<core::CompressedTexture> texture = core::loadCompressedTexture(file.toStdString());
    if (!texture) {
      printError(QString::fromStdString(texture.error()));  // it names the file
      return kExitFailure;
    }
    if (texture->levels.empty()) {
      printError(QStringLiteral("%1: holds no texture level").arg(file));
      return kExitFailure;
    }
    const core::CompressedLevel& top = texture->levels.front();
    if (top.width != map.width() || top.height != map.height()) {
      printError(QStringLiteral("%1: %2x%3 texels, but the preset's %4 map is %5x%6")
                     .arg(file)
                     .arg(top.width)
                     .arg(top.height)
                     .arg(slotName)
                     .arg(map.width())
                     .arg(map.height()));
      return kExitFailure;
    }
    textures.push_back(std::move(texture).value());
  }
  const auto report = [&](std::size_t done) {
    if (progressLines) {
      std::fprintf(stderr, "progress %.2f\n", double(done) / double(files.size() + 1));
      std::fflush(stderr);
    }
  };
  core::Result<renderer::RenderedViews> original =
      renderer::renderErrorViews(offscreen, material, frame, width, height);
  if (!original) {
    printError(QStringLiteral("compare --rendered: ") + QString::fromStdString(original.error()));
    return kExitFailure;
  }
  report(1);
  QJsonArray candidates;
  QString text;
  for (qsizetype i = 0; i < files.size(); ++i) {
    const QString& file = files[i];
    core::CompressedTexture& texture = textures[std::size_t(i)];
    core::Result<core::Image> decoded = core::decodeAsMap(texture);
    if (!decoded) {
      printError(QStringLiteral("%1: %2").arg(file, QString::fromStdString(decoded.error())));
      return kExitFailure;
    }
    const QString format = qstr(core::textureFormatInfo(texture.format).name);
    core::Material compressed = material;
    compressed.setCompressedMap(slot,
                                std::make_shared<const core::CompressedTexture>(std::move(texture)),
                                std::make_shared<const core::Image>(std::move(decoded).value()));
    core::Result<renderer::RenderedViews> views =
        renderer::renderErrorViews(offscreen, compressed, frame, width, height);
    if (!views) {
      printError(QStringLiteral("%1: %2").arg(file, QString::fromStdString(views.error())));
      return kExitFailure;
    }
    views->heightTexels = original->heightTexels;
    const std::vector<renderer::RenderedErrorRow> rows =
        renderer::compareRenderedViews(original.value(), views.value());
    const double flip = renderer::meanFlip(rows), psnr = renderer::meanPsnr(rows);
    candidates.append(
        QJsonObject{{QStringLiteral("file"), file},
                    {QStringLiteral("format"), format},
                    {QStringLiteral("flip"), flip},
                    {QStringLiteral("psnr"), std::isinf(psnr) ? QJsonValue() : QJsonValue(psnr)},
                    {QStringLiteral("views"), viewRows(rows)}});
    text += QStringLiteral("%1 (%2): FLIP %3, PSNR %4\n")
                .arg(QFileInfo(file).fileName(), format)
                .arg(flip, 0, 'f', 4)
                .arg(std::isinf(psnr) ? QStringLiteral("identical")
                                      : QStringLiteral("%1 dB").arg(psnr, 0, 'f', 2));
    report(std::size_t(i) + 2);
  }
  if (!json) {
    printOut(QStringLiteral("the %1 map alone compressed, mean of the close, grazing and far "
                            "views:\n")
                 .arg(slotName) +
             text);
    return kExitOk;
  }
  printJson(QJsonObject{{QStringLiteral("slot"), slotName},
                        {QStringLiteral("width"), width},
                        {QStringLiteral("height"), height},
                        {QStringLiteral("candidates"), candidates}});
  return kExitOk;
}

int printCostTable(renderer::OffscreenRenderer& offscreen, const renderer::FrameSettings& frame,
                   int width, int height, double maxMeanTexels, bool json) {
  // Enough frames for the fastest to settle on a busy machine, few enough for seven or more
  // techniques in seconds.
  const renderer::FrameTiming timing{5, 0.3, 40};
  core::Result<renderer::CostTable> table =
      offscreen.measureCostTableFrames(frame, width, height, timing);
  if (!table) {
    printError(QStringLiteral("render --cost-table: ") + QString::fromStdString(table.error()));
    return kExitFailure;
  }
  renderer::measureCostTableErrors(table.value());
  if (!json) {
    printOut(QString::fromStdString(renderer::describeCostTable(table.value(), maxMeanTexels)));
    return kExitOk;
  }
  const std::optional<std::size_t> cheapest =
      renderer::cheapestWithin(table.value(), maxMeanTexels);
  QJsonArray rows;
  for (std::size_t i = 0; i < table->rows.size(); ++i) {
    const renderer::CostTableRow& row = table->rows[i];
    rows.append(QJsonObject{
        {QStringLiteral("label"), QString::fromStdString(row.label)},
        {QStringLiteral("technique"), qstr(core::techniqueName(row.material.technique()))},
        {QStringLiteral("minSamples"), row.material.parameter(core::ParamId::MinSamples)},
        {QStringLiteral("maxSamples"), row.material.parameter(core::ParamId::MaxSamples)},
        {QStringLiteral("frame_ms_min"), row.times.fastest},
        {QStringLiteral("frame_ms"), row.times.median},
        {QStringLiteral("frames"), row.times.frames},
        {QStringLiteral("uvErrorTexels"),
         QJsonObject{{QStringLiteral("mean"), row.meanError},
                     {QStringLiteral("p95"), row.p95Error},
                     {QStringLiteral("pixels"), double(row.pixels)}}},
        {QStringLiteral("cheapest"), cheapest == i},
    });
  }
  printJson(QJsonObject{
      {QStringLiteral("rows"), rows},
      {QStringLiteral("maxError"), maxMeanTexels},
      {QStringLiteral("cheapest"),
       cheapest ? QJsonValue(QString::fromStdString(table->rows[*cheapest].label)) : QJsonValue()},
      {QStringLiteral("width"), width},
      {QStringLiteral("height"), height},
  });
  return kExitOk;
}

}  // namespace relief::cli
