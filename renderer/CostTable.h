// The cost table: for the current material and view, each technique (normal, parallax, POM at
// three sample counts, relief, cone, quadtree, displacement) with its frame time and its UV
// error against the exact trace, so an artist can pick the cheapest technique within the error
// they accept. `relief-cli render --cost-table` prints it; the viewport's Cost Table window
// shows it and applies a row.
//
// Frame times are CPU-clock times of frames drawn and finished (glFinish), the fastest of
// several: GL timer queries are not used, llvmpipe reports nonsense for them, and the fastest
// frame is the figure other processes disturb least (FrameTimes.h). Errors are measured as the
// error view measures them, against one exact trace of the view's eye rays shared by every row.
// In two parts: the GL passes (context current) and the exact trace (seconds, any thread).
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"
#include "core/material/Material.h"
#include "core/tracing/HeightField.h"
#include "renderer/FrameSettings.h"
#include "renderer/FrameTimes.h"

#include <atomic>
#include <optional>
#include <string>
#include <vector>

namespace relief::renderer {

class MaterialRenderer;

struct CostTableRow {
  std::string label;        // "pom 8-32": the technique, and its sample counts when they were set
  core::Material material;  // the material as the row draws it (technique, samples)
  FrameTimes times;
  core::Image finalUv;     // the row's float uv view (dropped once the error is measured)
  double meanError = 0.0;  // texels, over the compared pixels
  double p95Error = 0.0;
  long long pixels = 0;  // compared pixels
};

struct CostTable {
  std::vector<CostTableRow> rows;
  core::Image eyeRays;
  core::HeightField field{core::Image(1, 1, 1), 0, 0.0, 0.0, false};
};

// Draws and times every row, and renders what the errors need. The renderer's material is the
// base of every row and is restored afterwards.
core::Result<CostTable> measureCostTableFrames(MaterialRenderer& renderer,
                                               const FrameSettings& frame, int width, int height,
                                               const FrameTiming& timing);

// The exact trace and every row's error (`cancel` stops early, leaving the errors unset).
void measureCostTableErrors(CostTable& table, const std::atomic<bool>* cancel = nullptr);

// The row with the fastest frame among those whose mean error is at most `maxMeanTexels` and
// which compared pixels; none when no row qualifies.
std::optional<std::size_t> cheapestWithin(const CostTable& table, double maxMeanTexels);

// A text table, one row a line, the cheapest within `maxMeanTexels` marked with '*'.
std::string describeCostTable(const CostTable& table, double maxMeanTexels);

}  // namespace relief::renderer
