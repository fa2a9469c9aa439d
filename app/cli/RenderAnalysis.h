// `relief-cli render`'s analyses of a view rather than a picture of it: the engine grid
// (--engine grid, renderer/EngineGrid.h) and the cost table (--cost-table,
// renderer/CostTable.h).
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"
#include "core/preset/MaterialPreset.h"
#include "renderer/FrameSettings.h"

#include <QJsonObject>
#include <QStringList>

#include <array>

namespace relief::renderer {
class OffscreenRenderer;
}

namespace relief::cli {

// Draws the engine grid (a panel of width x height each), prints each panel's UV error
// (unless `json`, when it goes into `report` as "panels") and returns the captioned picture.
core::Result<core::Image> renderEngineGrid(renderer::OffscreenRenderer& offscreen,
                                           const renderer::FrameSettings& frame, int width,
                                           int height, bool json, QJsonObject& report);

// Compresses every map `compression` chooses (with the chain it ships with), renders `material`
// with the original and the compressed maps from each of renderer/RenderedError.h's views and
// prints their differences (text, or one JSON object); the exit code.
int printCompressionError(renderer::OffscreenRenderer& offscreen, const core::Material& material,
                          const std::array<core::MapCompression, core::kMapSlotCount>& compression,
                          const renderer::FrameSettings& frame, int width, int height, bool json);

// Renders `material` as it is and with each of `files` (DDS or KTX2, with the mip chain each
// holds) in place of its `slot` map alone, from each of renderer/RenderedError.h's views, and
// prints one row a file: the mean FLIP and PSNR over the views (text, or one JSON object with
// the views too); "progress F" lines on standard error with `progressLines`. The exit code: a
// file that cannot be read or decoded is named and fails the command.
int printCandidateErrors(renderer::OffscreenRenderer& offscreen, const core::Material& material,
                         core::MapSlot slot, const QStringList& files,
                         const renderer::FrameSettings& frame, int width, int height, bool json,
                         bool progressLines);

// Measures and prints the cost table (text, or one JSON object); the exit code.
int printCostTable(renderer::OffscreenRenderer& offscreen, const renderer::FrameSettings& frame,
                   int width, int height, double maxMeanTexels, bool json);

}  // namespace relief::cli
