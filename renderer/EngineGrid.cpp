// EngineGrid; see EngineGrid.h.
#include "renderer/EngineGrid.h"

#include "renderer/ImageConversion.h"
#include "renderer/MaterialRenderer.h"

#include <QFont>
#include <QPainter>

#include <cstdio>

namespace relief::renderer {
namespace {

std::string panelLabel(const std::optional<core::Engine>& engine) {
  return engine ? std::string(core::engineInfo(*engine).label) : std::string("Relief exact");
}

// The material traced exactly: the quadtree finds the same surface as the CPU tracer.
core::Material exactMaterial(const core::Material& material) {
  core::Material exact = material;
  if (material.technique() != core::Technique::Normal && material.hasMap(core::MapSlot::Height))
    exact.setTechnique(core::Technique::Quadtree);
  return exact;
}

}  // namespace

core::Result<std::vector<EngineGridPanelRender>> renderEngineGridPanels(MaterialRenderer& renderer,
                                                                        const FrameSettings& frame,
                                                                        int panelWidth,
                                                                        int panelHeight) {
  const core::Material material = renderer.material();
  std::vector<std::optional<core::Engine>> engines = {std::nullopt};
  for (const core::EngineInfo& info : core::allEngines())
    engines.emplace_back(info.engine);

  std::vector<EngineGridPanelRender> panels;
  for (const std::optional<core::Engine>& engine : engines) {
    renderer.setMaterial(engine ? material : exactMaterial(material));
    FrameSettings pass = frame;
    pass.split.reset();
    pass.engine = engine;
    pass.debugView = core::DebugView::Shading;
    pass.output = FrameOutput::Display;
    core::Result<core::Image> shaded = renderer.renderToImage(pass, panelWidth, panelHeight);
    core::Result<ErrorViewInputs> inputs =
        renderErrorViewInputs(renderer, pass, panelWidth, panelHeight);
    if (!shaded || !inputs) {
      renderer.setMaterial(material);
      return core::makeError(!shaded ? shaded.error() : inputs.error());
    }
    panels.push_back({engine, std::move(shaded).value(), std::move(inputs).value()});
  }
  renderer.setMaterial(material);
  return panels;
}

EngineGrid composeEngineGrid(const std::vector<EngineGridPanelRender>& panels,
                             const std::atomic<bool>* cancel) {
  EngineGrid grid;
  if (panels.empty())
    return grid;
  const int panelWidth = panels.front().shaded.width();
  const int panelHeight = panels.front().shaded.height();
  for (const EngineGridPanelRender& render : panels) {
    if (cancel && cancel->load())
      break;
    grid.panels.push_back(
        {render.engine, panelLabel(render.engine),
         core::computeUvErrorMap(render.errorInputs.finalUv, render.errorInputs.eyeRays,
                                 render.errorInputs.field, {}, cancel)});
  }

  constexpr int kGap = 4;
  QImage picture(int(panels.size()) * (panelWidth + kGap) - kGap, panelHeight,
                 QImage::Format_RGBA8888);
  picture.fill(QColor(24, 24, 24));
  QPainter painter(&picture);
  QFont font = painter.font();
  font.setPixelSize(std::max(11, panelHeight / 28));
  painter.setFont(font);
  const int line = painter.fontMetrics().height();
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const int left = int(i) * (panelWidth + kGap);
    painter.drawImage(left, 0, toDisplayImage(panels[i].shaded));
    if (i >= grid.panels.size())
      continue;
    // Captions on a dark band at the top, readable over any material.
    const QRect band(left, 0, panelWidth, 2 * line + line / 2);
    painter.fillRect(band, QColor(0, 0, 0, 170));
    painter.setPen(Qt::white);
    painter.drawText(band.adjusted(line / 3, line / 6, 0, 0), Qt::AlignLeft | Qt::AlignTop,
                     QString::fromStdString(grid.panels[i].label));
    painter.setPen(QColor(255, 214, 120));
    painter.drawText(band.adjusted(line / 3, line + line / 4, 0, 0), Qt::AlignLeft | Qt::AlignTop,
                     QString::fromStdString(engineGridErrorCaption(grid.panels[i])));
  }
  painter.end();
  grid.picture = fromQImage(picture);
  return grid;
}

std::string engineGridErrorCaption(const EngineGridPanel& panel) {
  char text[128];
  if (panel.error.pixels == 0)
    std::snprintf(text, sizeof(text), "UV error: map minified everywhere, move closer");
  else
    std::snprintf(text, sizeof(text), "UV error: mean %.2f, p95 %.2f texels", panel.error.mean,
                  panel.error.p95);
  return text;
}

std::string describeEngineGrid(const EngineGrid& grid) {
  std::string text;
  for (const EngineGridPanel& panel : grid.panels)
    text += panel.label + ": " + core::describeUvError(panel.error) + "\n";
  return text;
}

}  // namespace relief::renderer
