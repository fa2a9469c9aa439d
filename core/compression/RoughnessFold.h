// The normals' spread folded into the roughness map's mips (Toksvig, "Mipmapping Normal Maps",
// 2005; in the von Mises-Fisher form of Neubelt and Pettineo, "Crafting a Next-Gen Material
// Pipeline for The Order: 1886", 2013). Averaging unit normals over a mip texel's footprint gives
// a shorter vector wherever they disagree: renormalised, a bumpy surface far away turns into a
// smooth mirror with a tight highlight that shimmers. The length r of the average says how
// spread the normals are; the spread is added to the GGX lobe's width instead:
//   kappa = (3r - r^3) / (1 - r^2)        (the vMF concentration, Banerjee et al. 2005)
//   alpha'^2 = alpha^2 + 2 / kappa        (a vMF of concentration kappa is a Beckmann/GGX-like
//                                          lobe of alpha^2 = 2 / kappa near its peak)
// with alpha = roughness^2 (glTF's perceptual roughness). Near r = 1, 1 / kappa = 1 - r, so the
// rule is Toksvig's 1/s' = 1/s + (1 - r)/r written for alpha.
#pragma once

#include "core/compression/MipChain.h"
#include "core/image/Image.h"

#include <vector>

namespace relief::core::inline compression {

// The perceptual roughness that holds `roughness` widened by normals whose average has length
// `meanNormalLength` (0..1], clamped to 1; unchanged at length 1.
double foldedRoughness(double roughness, double meanNormalLength);

// Levels 1.. of the roughness chain with the spread of `normals` (a normal map, 0.5 + 0.5 n)
// folded in: the roughness filtered by `filter` as any data map, each texel widened by the
// normals under its footprint (their unnormalised box average, from level 0's unit vectors).
// `roughness` and `normals` must be the same size. One channel (the roughness map's first).
std::vector<Image> foldedRoughnessLevels(const Image& roughness, const Image& normals,
                                         MipFilter filter);

// The lengths of the averaged unit normals under each texel of levels 1.. (one channel each):
// what foldedRoughnessLevels folds in, for tests and the docs' numbers.
std::vector<Image> meanNormalLengths(const Image& normals);

}  // namespace relief::core::inline compression
