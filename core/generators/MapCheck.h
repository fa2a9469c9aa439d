// Maps that check each other: whether a normal map is OpenGL (+Y up) or DirectX (+Y down),
// whether a height map stores height or depth, and whether a normal map and a height map belong
// together at all. Mistakes of this kind look like a broken shader (lighting from the wrong
// side, holes where bumps should be), so they are found from the pixels, with their evidence.
//
// Two measures, both on the slopes a normal map encodes (p, q) = (-nx / nz, -ny / nz), which
// for an OpenGL map of a height field h are s * (dh/dx, dh/dy) with y up (NormalFromHeight.h):
// - With a height map: the correlation of p with dh/dx and of q with dh/dy (Pearson, over every
//   texel). +1 on both: the pair agrees as declared. q alone negative: the normal map's Y is
//   flipped (DirectX). Both negative: the height map is inverted (depth). Both near 0: the maps
//   are of different surfaces. The least-squares slope of (p, q) on the gradient is the
//   normal-from-height strength that would reproduce the normal map.
// - Without one: a height field's slopes have no curl (dp/dy = dq/dx), and flipping Y gives
//   them curl, so the mean squared curl of (p, q) as stored, against that with q negated, says
//   which convention the normal map follows (the integrability condition of shape from
//   shading, Frankot and Chellappa 1988).
#pragma once

#include "core/base/Result.h"
#include "core/generators/NormalFromHeight.h"
#include "core/image/Image.h"

#include <optional>
#include <string>
#include <vector>

namespace relief::core::inline generators {

// How strong the evidence must be. The pair matches when either axis correlates at least at
// kMapCheckThreshold: pairs made from one surface reach 0.9 and up (artists' pairs in game data
// 0.55 and up on their stronger axis), while two different brick and tile patterns whose mortar
// lines partly coincide reached 0.42. Then an axis whose |correlation| reaches kAxisThreshold
// gives its sign (a strip of trim has little slope across it). The curl decides the convention
// alone when one reading's curl is under kCurlRatioThreshold times the other's.
inline constexpr double kMapCheckThreshold = 0.5;
inline constexpr double kAxisThreshold = 0.2;
inline constexpr double kCurlRatioThreshold = 0.5;

struct MapCheckResult {
  // Normal map alone: mean squared curl of the slopes as stored and with Y flipped.
  double curlAsStored = 0.0;
  double curlFlipped = 0.0;
  // With a height map (nullopt without one): correlations per axis and the fitted strength.
  std::optional<double> correlationX;
  std::optional<double> correlationY;
  std::optional<double> strength;

  // The verdicts; nullopt where the evidence is too weak.
  std::optional<NormalConvention> convention;
  std::optional<bool> heightIsDepth;  // with a height map only
  bool pairMatches = true;            // false when a height map was given and nothing agrees
};

// Checks `normal` (RGB or RG holding n * 0.5 + 0.5, as loaded; Z rebuilt when there are two
// channels) and, when given, `height` (first channel; resized to the normal map's size when it
// has the same shape at another resolution). Fails with a message naming the problem (a
// one-channel "normal" map, maps of different shapes).
Result<MapCheckResult> checkMaps(const Image& normal, const Image* height);

// The findings against what the material declares (its normal map's Y convention and whether
// its height map is depth), one sentence each with the evidence; empty when the maps agree with
// the declaration. `normalName` and `heightName` name the maps (file names) in the sentences.
std::vector<std::string> mapCheckFindings(const MapCheckResult& result,
                                          NormalConvention declaredConvention,
                                          bool declaredHeightIsDepth, const std::string& normalName,
                                          const std::string& heightName);

}  // namespace relief::core::inline generators
