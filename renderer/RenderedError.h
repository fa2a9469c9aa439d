// The error compression makes where the artist looks: the material rendered with its original
// maps and with their compressed versions (each sampled through the mip chain it ships with),
// from the same views and light, compared as pictures (PSNR and FLIP of the displayed frame) and,
// for the relief, by how far the parallax-mapped texture coordinate moves (the float UV view of
// both, in texels of the height map). Texel metrics judge level 0 of one map; this judges the
// material, every map and level at once, close, grazing and far away. `relief-cli compare
// --rendered PRESET` (render --compression-error) prints it.
#pragma once

#include "core/base/Result.h"
#include "core/material/Material.h"
#include "renderer/FrameSettings.h"

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace relief::renderer {

class OffscreenRenderer;

// A view the error is measured from: the frame's camera at this pitch, seen from `distance`
// times farther (TilePreview::distance: mip levels log2(distance) further down).
struct RenderedErrorView {
  const char* name;
  float pitchDeg;
  int distance;
};
// close (35 degrees), grazing (12 degrees), far (35 degrees, 8 times farther).
std::span<const RenderedErrorView> renderedErrorViews();

struct RenderedErrorRow {
  std::string view;
  double psnr = 0.0;               // dB over RGB of the displayed frames; infinity when identical
  double mse = 0.0;                // the squared error PSNR comes from (0..1 values)
  double flipMean = 0.0;           // FLIP (LDR), mean over the frame
  double uvShiftMeanTexels = 0.0;  // |final UV difference| in height-map texels, covered pixels
  double uvShiftP95Texels = 0.0;
};

// A material rendered from each view: the displayed picture (RGB) and, when it has relief, the
// float UV view; heightTexels is its height map's size (0 without one).
struct RenderedViews {
  std::vector<core::Image> pictures;
  std::vector<core::Image> uvs;
  std::pair<double, double> heightTexels{0.0, 0.0};
};
core::Result<RenderedViews> renderErrorViews(OffscreenRenderer& offscreen,
                                             const core::Material& material,
                                             const FrameSettings& frame, int width, int height);
// One row a view: the error of `compressed` against `original` (both from renderErrorViews with
// the same frame and size; UV shifts in the original's height texels).
std::vector<RenderedErrorRow> compareRenderedViews(const RenderedViews& original,
                                                   const RenderedViews& compressed);

// Renders `original` and `compressed` (the same material, with compression previews in some
// slots) from each view at width x height; `frame` gives the camera's yaw and distance, the
// light, environment, mesh chains and tile preview. The offscreen renderer's mesh must be set;
// its material is left as `original`. The two calls above, one after the other.
core::Result<std::vector<RenderedErrorRow>> measureRenderedError(OffscreenRenderer& offscreen,
                                                                 const core::Material& original,
                                                                 const core::Material& compressed,
                                                                 const FrameSettings& frame,
                                                                 int width, int height);

// One line a view: "close  PSNR 41.23 dB  FLIP 0.0123  UV shift 0.012 texels mean, 0.05 p95".
std::string describeRenderedError(const std::vector<RenderedErrorRow>& rows);

}  // namespace relief::renderer
