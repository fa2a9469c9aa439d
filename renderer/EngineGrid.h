// The engine grid: one view and light of the material drawn by Relief's exact trace and by each
// engine preview mode (core/exporters/EnginePreview.h) side by side, each captioned with its
// mean UV error against the exact trace, so an artist sees before exporting where an engine's
// relief will band, swim or flatten. `relief-cli render --engine grid` and the viewport's
// Engine Grid window draw it.
//
// In two parts, as the error view is: the GL passes (context current, quick), then the exact
// CPU trace of every panel and the picture (seconds, any thread).
#pragma once

#include "core/base/Result.h"
#include "core/exporters/EnginePreview.h"
#include "core/image/Image.h"
#include "core/tracing/UvErrorMap.h"
#include "renderer/ErrorView.h"
#include "renderer/FrameSettings.h"

#include <atomic>
#include <optional>
#include <string>
#include <vector>

namespace relief::renderer {

class MaterialRenderer;

struct EngineGridPanelRender {
  std::optional<core::Engine> engine;  // none: Relief's exact trace
  core::Image shaded;                  // the frame as shown (sRGB RGBA8 values)
  ErrorViewInputs errorInputs;
};

struct EngineGridPanel {
  std::optional<core::Engine> engine;
  std::string label;  // "Relief exact", "Godot 4", ...
  core::UvErrorMap error;
};

struct EngineGrid {
  core::Image picture;  // the panels in a row, captioned (sRGB RGBA)
  std::vector<EngineGridPanel> panels;
};

// The panels' GL passes with the renderer's material: Relief's exact trace (the quadtree, when
// the material has a relief; otherwise the material as it is), then every engine. The frame's
// own engine and debug view are replaced; its view, light and tile preview are kept.
core::Result<std::vector<EngineGridPanelRender>> renderEngineGridPanels(MaterialRenderer& renderer,
                                                                        const FrameSettings& frame,
                                                                        int panelWidth,
                                                                        int panelHeight);

// Traces every panel exactly and composes the captioned picture. `cancel` stops early (the
// result is then partial).
EngineGrid composeEngineGrid(const std::vector<EngineGridPanelRender>& panels,
                             const std::atomic<bool>* cancel = nullptr);

// "Godot 4: mean 0.41, p95 1.9 texels", a line per panel (the CLI's text output).
std::string describeEngineGrid(const EngineGrid& grid);
// The caption of one panel's error: "UV error: mean 0.41, p95 1.90 texels".
std::string engineGridErrorCaption(const EngineGridPanel& panel);

}  // namespace relief::renderer
