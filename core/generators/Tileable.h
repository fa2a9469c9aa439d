// Making a photograph (and every map aligned with it) tile without a visible seam, the first step
// from a photo to a material. Two methods:
//
// - Quilt (image quilting, Efros and Freeman 2001): over each wrap-around seam a patch of the
//   image's own texels is laid, taken from where its borders best match the texels it overlaps;
//   it is joined to them along the minimum-error path through the overlap (dynamic programming,
//   the path closed around the other axis so the tile's corners join too), feathered over a few
//   texels. Everything else is the photo, untouched. For structured textures (bricks, tiles,
//   bark) where blending would ghost.
// - CrossFade (Heitz and Neyret 2018, "High-Performance By-Example Noise using a
//   Histogram-Preserving Blending Operator"): the photo is blended with itself shifted by half
//   its size, in a space where every channel's histogram is Gaussian, with the variance-
//   preserving weights w1 / sqrt(w1^2 + w2^2); so the blend keeps the photo's contrast and
//   histogram where a plain cross-fade would wash it out. For smooth, stochastic textures
//   (sand, plaster, grass) where any cut would show.
//
// The cut (or blend) is decided once, from all maps together, and applied identically to every
// map, so colour, height, normal and the rest stay aligned. An axis whose wrap seam is already no
// stronger than the image's interior is left as it is.
#pragma once

#include "core/base/Result.h"
#include "core/base/WorkControl.h"
#include "core/image/Image.h"

#include <span>
#include <vector>

namespace relief::core::inline generators {

enum class TileMethod { Quilt, CrossFade };

// How the blending treats a map: normal maps are blended as vectors and renormalised.
enum class TileMapRole { Data, Normal };

struct TileMap {
  const Image* image = nullptr;
  TileMapRole role = TileMapRole::Data;
};

struct TileableOptions {
  TileMethod method = TileMethod::Quilt;
  // Quilt: width in texels of the patch laid over each wrap seam (its outer thirds are cut into
  // the image); 0 picks a third of the image's shorter side. At most half that side (the patch
  // needs somewhere else to come from).
  int patch = 0;
  int feather = 2;     // quilt: texels on each side of a cut that are blended
  bool recut = false;  // make an axis anew even when it already tiles
};

struct TileAxisReport {
  bool alreadyTiled = false;  // left as it was
  double seamBefore = 0.0;    // wrapSeamRatio of the first map before and after
  double seamAfter = 0.0;
  // Quilt: the first column (row) the patch is taken from; cross-fade: the shift of the copy.
  int source = -1;
  // Quilt: the squared difference of the texels on either side of the cuts in the result,
  // relative to that of the texel pairs around them (1: the cut is as strong as the image's own
  // detail there), over all maps with each channel weighted by its variance.
  double cutRatio = 0.0;
};

struct TileableResult {
  std::vector<Image> maps;  // in the order given, same size, colour space and channels
  TileAxisReport horizontal, vertical;
};

// The wrap-around seam's strength: the squared difference between the last and the first column
// (row when `vertical`), summed over rows and channels, divided by the same sum for the pairs of
// neighbouring columns around it (the four on each side). About 1 for a texture that tiles: a
// seam is a step its neighbours do not have, while a mortar line or ridge that runs along the
// border raises its neighbours as much as the border.
double wrapSeamRatio(const Image& image, bool vertical);

// Fails with a message for no maps, maps of different sizes, a normal map with fewer than
// three channels, a patch larger than half the image, an image too small to tile, or when
// cancelled.
Result<TileableResult> makeTileable(std::span<const TileMap> maps, const TileableOptions& options,
                                    const WorkControl& control = {});

}  // namespace relief::core::inline generators
