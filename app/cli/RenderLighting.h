// The render command's light and display options: the directional light's intensity, the
// environment (pbr shading's image-based light and the background), exposure and tone mapping.
// Each overrides what the preset's view says.
#pragma once

#include "CliCommon.h"

#include "core/view/ViewState.h"
#include "renderer/RenderView.h"

namespace relief::cli {

CliOptions lightingOptions();

// Sets `view`'s light intensity, environment and display from the preset's `presetView` and
// the options. An environment file is read and checked here, so a bad one stops the command
// (exit 1) with a message naming it (and `presetPath` with the field, when the preset named it)
// instead of rendering with the fallback. Returns an exit code on error.
std::optional<int> applyLightingOptions(const QCommandLineParser& parser,
                                        const core::ViewState& presetView,
                                        const QString& presetPath, renderer::RenderView& view);

}  // namespace relief::cli
