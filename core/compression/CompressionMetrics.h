// How far a compressed map is from its original, in numbers that mean something for each kind
// of map: PSNR, SSIM and maximum error for colour and data; the angle between normals for
// normal maps; for height maps the parallax shift the error causes, in texels; and the size
// against uncompressed texels (reference 003's 6:1 and 4:1).
#pragma once

#include "core/compression/TextureFormat.h"
#include "core/image/Image.h"

#include <cstdint>
#include <vector>

namespace relief::core::inline compression {

struct ChannelError {
  double mse = 0.0;
  double psnr = 0.0;      // dB, peak 1.0; infinity when identical
  double maxError = 0.0;  // 0..1
};

struct ImageError {
  std::vector<ChannelError> channels;
  double mse = 0.0;  // over all channels
  double psnr = 0.0;
  double ssim = 1.0;  // mean over channels (Wang et al. 2004: 11x11 Gaussian, sigma 1.5)
  double maxError = 0.0;
};

// Compares the first min(channels) channels; the images must be the same size.
ImageError measureImageError(const Image& reference, const Image& candidate);

struct NormalError {
  double meanDegrees = 0.0;
  double p99Degrees = 0.0;
  double maxDegrees = 0.0;
  double shareAbove2Degrees = 0.0;  // 0..1
};

// Normals stored as 0.5 + 0.5 n (RGB); both are renormalised before the angle is taken.
NormalError measureNormalError(const Image& reference, const Image& candidate);

struct HeightError {
  // The shift of the parallax-mapped texture coordinate a height error causes at a 45 degree
  // view (offset = h * heightScale * V.xy / V.z, |V.xy / V.z| = 1), in texels of the map.
  double meanTexels = 0.0;
  double p99Texels = 0.0;
  double maxTexels = 0.0;
};

HeightError measureHeightError(const Image& reference, const Image& candidate, double heightScale);

// A high-dynamic-range map (BC6H) judged as HDR encoders are compared. Exposure PSNR is
// Munkberg et al. 2006's multi-exposure PSNR: the linear RGB values are scaled by 2^c for each
// stop c, gamma-corrected (1/2.2), clamped to 0..1 and quantised to 0..255 as a display would
// show that exposure, and the squared error of all stops gives one PSNR (peak 255). The stops
// are the seven around the reference's key: c0 - 3 .. c0 + 3, where 2^c0 takes the geometric
// mean luminance (Rec. 709) to 0.18, mid grey. The log error is the mean over texels and
// channels of |log2((|a| + e) / (|b| + e))| with e = 2^-14 (the smallest normal half), so a
// texel's error counts in stops whatever its brightness.
struct HdrError {
  double exposurePsnr = 0.0;  // dB, infinity when identical
  int firstStop = 0;
  int lastStop = 0;
  double meanLog2Error = 0.0;
  // The reference holds values beyond 0..1: then exposure PSNR, not PSNR at peak 1, is the
  // figure formats are ranked by (CompressionReport.h: headlineQuality).
  bool referenceIsHdr = false;
};

// Compares RGB (a single channel counts as grey); the images must be the same size.
HdrError measureHdrError(const Image& reference, const Image& candidate);

struct SizeFigures {
  std::uint64_t bytes = 0;
  double bitsPerPixel = 0.0;  // of level 0 alone: the format's rate
  double ratioToRgba8 = 0.0;  // 32 bits per pixel
  // Against 8 bits per channel of the map as it is (RGB 24: BC1 and ETC1 are 6:1, as in the
  // reference; RGBA 32: BC3 is 4:1; a one-channel height 8: BC4 is 2:1).
  double ratioToSource = 0.0;
  // What ships: the bytes of the KTX2 file the settings write, supercompressed with Zstandard
  // at zstdLevel when that is above 0. 0 when not measured.
  std::uint64_t ktx2Bytes = 0;
  int zstdLevel = 0;
};

SizeFigures measureSize(TextureFormat format, int sourceChannels, std::uint64_t bytesWithMips);

}  // namespace relief::core::inline compression
