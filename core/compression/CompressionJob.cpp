// CompressionJob; see CompressionJob.h.
#include "core/compression/CompressionJob.h"

#include "core/compression/TextureFile.h"

#include "core/base/Text.h"

#include <QElapsedTimer>

#include <cstdio>

namespace relief::core::inline compression {

std::string formatSlotProblem(TextureFormat format, MapSlot slot) {
  if (formatSuitsSlot(format, slot))
    return {};
  return std::string(textureFormatInfo(format).label) + " cannot hold a " +
         lowerCase(mapSlotLabel(slot)) + " map";
}

std::string formatMapProblem(const Image& map, TextureFormat format, bool acceptIntegerMaps) {
  if (!isHalfFloatFormat(format))
    return {};
  const std::string label(textureFormatInfo(format).label);
  if (map.sourceBitsPerChannel() == 8 && !acceptIntegerMaps) {
    return "it is an 8-bit map, and " + label +
           " stores half floats for HDR and float maps (use BC4 or BC7 for 8-bit maps, or "
           "convert it to float first)";
  }
  if (map.colorSpace() == ColorSpace::Srgb) {
    return "it is sRGB-encoded colour, and " + label +
           " stores linear values (an EXR or HDR image, or a float map)";
  }
  return {};
}

std::vector<std::string> compressionWarnings(const Image& map, TextureFormat format) {
  const TextureFormatInfo& info = textureFormatInfo(format);
  std::vector<std::string> warnings;
  if (isHalfFloatFormat(format)) {
    if (std::string clamps = describeHalfFloatClamps(
            countHalfFloatClamps(map, format == TextureFormat::Bc6hSigned), format);
        !clamps.empty())
      warnings.push_back(clamps);
  } else if (const double outside = shareOutsideUnitRange(map); outside > 0.0) {
    char percent[32];
    std::snprintf(percent, sizeof percent, "%.3g", outside * 100.0);
    warnings.push_back(std::string(percent) +
                       "% of the values lie outside 0..1 and are clamped (GPU formats store "
                       "0..1; normalise the map first to keep them)");
  }
  if (map.channels() >= 3 && isSingleChannelFormat(format)) {
    warnings.push_back("it has " + std::to_string(map.channels()) + " channels; " +
                       std::string(info.label) + " keeps only the first (red)");
  }
  return warnings;
}

Result<CompressionOutcome> runCompressionJob(const CompressionJob& job,
                                             const WorkControl& control) {
  if (std::string problem = formatSlotProblem(job.settings.format, job.slot); !problem.empty())
    return makeError(problem);
  if (std::string problem = formatMapProblem(*job.map, job.settings.format, job.acceptIntegerMaps);
      !problem.empty())
    return makeError(problem);
  QElapsedTimer timer;
  timer.start();
  Result<CompressedTexture> texture =
      compressMap(*job.map, job.slot, job.settings, control, job.spreadNormals.get());
  if (!texture)
    return makeError(texture.error());
  const double seconds = double(timer.nsecsElapsed()) * 1e-9;

  CompressionOutcome outcome;
  outcome.job = job;
  outcome.warnings = compressionWarnings(*job.map, job.settings.format);
  if (job.measure) {
    Result<Image> decoded = decodeAsMap(texture.value());
    if (!decoded)
      return makeError(decoded.error());
    outcome.report = makeCompressionReport(*job.map, decoded.value(), job.slot, job.heightScale);
    // Half floats are judged in float even on a map within 0..1 (an HDR map already is).
    if (isHalfFloatFormat(job.settings.format) && !outcome.report.hdr)
      outcome.report.hdr = measureHdrError(*job.map, decoded.value());
    outcome.decoded = std::make_shared<const Image>(std::move(decoded).value());
  }
  outcome.report.slot = job.slot;
  outcome.report.format = job.settings.format;
  outcome.report.encodeSeconds = seconds;
  outcome.report.size = measureSize(job.settings.format, job.map->channels(), texture->byteSize());
  if (job.measure) {
    outcome.report.size->ktx2Bytes = encodeKtx2(texture.value(), job.settings.zstdLevel).size();
    outcome.report.size->zstdLevel = job.settings.zstdLevel;
  }
  outcome.texture = std::make_shared<const CompressedTexture>(std::move(texture).value());
  return outcome;
}

TextureFormat suggestedFormat(MapSlot slot, int channels) {
  switch (mapSlotTexels(slot)) {
    case MapTexels::Colour:
      return channels == 4 ? TextureFormat::Bc7 : TextureFormat::Bc1;
    case MapTexels::Normal:
      return TextureFormat::Bc5;
    case MapTexels::Scalar:
      return TextureFormat::Bc4;
  }
  return TextureFormat::Bc4;  // not reached: every kind is handled above
}

}  // namespace relief::core::inline compression
