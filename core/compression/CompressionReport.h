// One comparison of a map with its compressed version, in the numbers that suit the map's kind
// (CompressionMetrics.h), as a person reads them and as JSON for pipelines. Shared by
// relief-cli's compress and compare commands and the Compress panel's tables.
#pragma once

#include "core/compression/CompressionMetrics.h"
#include "core/image/Image.h"
#include "core/material/MapSlot.h"

#include <QJsonObject>

#include <optional>
#include <string>

namespace relief::core::inline compression {

struct CompressionReport {
  MapSlot slot = MapSlot::Color;
  ImageError image;
  std::optional<NormalError> normal;  // normal maps
  std::optional<HeightError> height;  // height maps
  // Half-float formats (BC6H), and every format given a linear map beyond 0..1: judged in float.
  std::optional<HdrError> hdr;
  // FLIP (Flip.h) of the map as a viewer sees it: mean and 95th percentile, 0 = identical.
  double flip = 0.0;
  double flipP95 = 0.0;
  double heightScale = 0.0;
  std::optional<TextureFormat> format;  // when the candidate is a compressed texture
  std::optional<SizeFigures> size;
  double encodeSeconds = 0.0;  // 0 when not measured
};

// `reference` and `candidate` must be the same size (checked by the caller: the message names
// the files). For a normal map the angle is measured; for a height map the parallax shift at
// `heightScale`. `flipMap`, when given, receives FLIP's per-pixel error (Flip.h).
CompressionReport makeCompressionReport(const Image& reference, const Image& candidate,
                                        MapSlot slot, double heightScale, Image* flipMap = nullptr);

// The figure "compare all formats" ranks by, larger is better: PSNR in dB for colour and data
// (exposure PSNR for a map beyond 0..1: HDR), minus the mean angle in degrees for normals.
double headlineQuality(const CompressionReport& report);
std::string headlineQualityName(MapSlot slot);
// A map judged in float (HdrError): linear, 16 or 32 bits per channel, values beyond 0..1, and
// not a normal map.
bool isHdrMap(const Image& map, MapSlot slot);

QJsonObject reportToJson(const CompressionReport& report);
std::string reportToText(const CompressionReport& report);

}  // namespace relief::core::inline compression
