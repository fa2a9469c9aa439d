// The compression workflow, written once: check that a format suits a map, warn about what it
// will lose (values clamped to 0..1, channels dropped), compress with progress and cancel, time
// it, decode the blocks back and measure them against the original. relief-cli compress, the
// Compress panel, compare-all-formats and package export all run maps through here; they only
// differ in how they show the result. Also the default choice of a format for a map slot.
#pragma once

#include "core/base/Result.h"
#include "core/base/WorkControl.h"
#include "core/compression/CompressionReport.h"
#include "core/compression/Compressor.h"
#include "core/compression/TextureFile.h"
#include "core/material/MapSlot.h"
#include "core/material/Parameters.h"

#include <memory>
#include <string>
#include <vector>

namespace relief::core::inline compression {

struct CompressionJob {
  std::shared_ptr<const Image> map;
  MapSlot slot = MapSlot::Color;
  CompressionSettings settings;
  // The parallax height scale the height metric assumes (the material's heightScale).
  double heightScale = parameterDefault(ParamId::HeightScale);
  // Decode and measure the result (the report); package export only needs the blocks.
  bool measure = true;
  // The normal map a roughness map's mips fold in (settings.roughnessFromNormals).
  std::shared_ptr<const Image> spreadNormals = nullptr;
  // Half-float formats take an 8-bit map only when asked (formatMapProblem).
  bool acceptIntegerMaps = false;
};

struct CompressionOutcome {
  CompressionJob job;
  std::shared_ptr<const CompressedTexture> texture;
  std::shared_ptr<const Image> decoded;  // null unless measured
  CompressionReport report;              // format, size and time always; metrics when measured
  // What the artist should know, e.g. "62% of the values lie outside 0..1 and are clamped".
  std::vector<std::string> warnings;
};

// Why the format cannot hold a map of this slot ("BC4 (ATI1) cannot hold a colour map"), or
// empty when it can. Cheap: the CLI asks before loading anything else.
std::string formatSlotProblem(TextureFormat format, MapSlot slot);
// Why `format` should not take `map`, or empty: a half-float format (BC6H) refuses an 8-bit
// map unless `acceptIntegerMaps` (its 0..1 values would spend 16 bits on 8 bits' worth, and
// an 8-bit map given to BC6H is usually the wrong file or the wrong format), and sRGB-encoded
// colour always (BC6H has no sRGB form: it holds linear values).
std::string formatMapProblem(const Image& map, TextureFormat format, bool acceptIntegerMaps);
// What compressing `map` into `format` loses that the artist should know (values clamped to
// 0..1, channels dropped).
std::vector<std::string> compressionWarnings(const Image& map, TextureFormat format);

// Runs one job. Fails with "cancelled" when cancelled, or with the reason the format cannot
// hold the map; the message does not name the map (callers add its file or slot).
Result<CompressionOutcome> runCompressionJob(const CompressionJob& job,
                                             const WorkControl& control = {});

// The usual choice for a map: BC1 (BC7 with alpha: BC3's size, and its colour is far better
// than BC3's BC1 half) for colour, BC5 for normals, BC4 for single-value maps; what the
// Compress panel picks when the artist has chosen nothing.
TextureFormat suggestedFormat(MapSlot slot, int channels);

}  // namespace relief::core::inline compression
