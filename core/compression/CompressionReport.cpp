// CompressionReport; see CompressionReport.h.
#include "core/compression/CompressionReport.h"

#include "core/compression/Compressor.h"
#include "core/compression/Flip.h"

#include <QJsonArray>

#include <cmath>
#include <cstdio>

namespace relief::core::inline compression {
namespace {

// JSON has no infinity: an exact match reports PSNR as null.
QJsonValue decibels(double value) {
  return std::isfinite(value) ? QJsonValue(value) : QJsonValue(QJsonValue::Null);
}

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c, d);
  return buffer;
}

std::string decibelText(double value) {
  return std::isfinite(value) ? format("%.2f dB", value) : std::string("exact");
}

const char* kChannelNames[] = {"R", "G", "B", "A"};

}  // namespace

CompressionReport makeCompressionReport(const Image& reference, const Image& candidate,
                                        MapSlot slot, double heightScale, Image* flipMap) {
  CompressionReport report;
  report.slot = slot;
  report.image = measureImageError(reference, candidate);
  FlipResult flip = measureFlip(reference, candidate);
  report.flip = flip.mean;
  report.flipP95 = flip.p95;
  if (flipMap)
    *flipMap = std::move(flip.errorMap);
  if (slot == MapSlot::Normal)
    report.normal = measureNormalError(reference, candidate);
  if (slot == MapSlot::Height) {
    report.height = measureHeightError(reference, candidate, heightScale);
    report.heightScale = heightScale;
  }
  // An HDR map is judged in float too, whatever holds the candidate, so that its formats and
  // other tools' files compare.
  if (isHdrMap(reference, slot))
    report.hdr = measureHdrError(reference, candidate);
  return report;
}

bool isHdrMap(const Image& map, MapSlot slot) {
  return slot != MapSlot::Normal && map.colorSpace() == ColorSpace::Linear &&
         map.sourceBitsPerChannel() >= 16 && shareOutsideUnitRange(map) > 0.0;
}

double headlineQuality(const CompressionReport& report) {
  if (report.hdr && report.hdr->referenceIsHdr)
    return report.hdr->exposurePsnr;
  return report.normal ? -report.normal->meanDegrees : report.image.psnr;
}

std::string headlineQualityName(MapSlot slot) {
  return slot == MapSlot::Normal ? "mean angular error (degrees)" : "PSNR (dB)";
}

QJsonObject reportToJson(const CompressionReport& report) {
  QJsonObject json;
  json["slot"] = QString::fromUtf8(mapSlotName(report.slot).data());
  if (report.format)
    json["format"] = QString::fromUtf8(textureFormatInfo(*report.format).name.data());
  QJsonArray channels;
  for (std::size_t c = 0; c < report.image.channels.size(); ++c) {
    const ChannelError& error = report.image.channels[c];
    channels.append(QJsonObject{{"channel", kChannelNames[c]},
                                {"psnr", decibels(error.psnr)},
                                {"mse", error.mse},
                                {"maxError", error.maxError}});
  }
  json["channels"] = channels;
  json["psnr"] = decibels(report.image.psnr);
  json["mse"] = report.image.mse;
  json["ssim"] = report.image.ssim;
  json["flip"] = QJsonObject{{"mean", report.flip}, {"p95", report.flipP95}};
  json["maxError"] = report.image.maxError;
  if (report.normal) {
    json["angularError"] = QJsonObject{{"meanDegrees", report.normal->meanDegrees},
                                       {"p99Degrees", report.normal->p99Degrees},
                                       {"maxDegrees", report.normal->maxDegrees},
                                       {"shareAbove2Degrees", report.normal->shareAbove2Degrees}};
  }
  if (report.height) {
    json["parallaxShift"] = QJsonObject{{"heightScale", report.heightScale},
                                        {"meanTexels", report.height->meanTexels},
                                        {"p99Texels", report.height->p99Texels},
                                        {"maxTexels", report.height->maxTexels}};
  }
  if (report.hdr) {
    json["hdr"] = QJsonObject{{"exposurePsnr", decibels(report.hdr->exposurePsnr)},
                              {"firstStop", report.hdr->firstStop},
                              {"lastStop", report.hdr->lastStop},
                              {"meanLog2Error", report.hdr->meanLog2Error}};
  }
  if (report.size) {
    json["bytes"] = double(report.size->bytes);
    json["bitsPerPixel"] = report.size->bitsPerPixel;
    json["ratioToRgba8"] = report.size->ratioToRgba8;
    json["ratioToSource"] = report.size->ratioToSource;
    if (report.size->ktx2Bytes > 0) {
      json["ktx2Bytes"] = double(report.size->ktx2Bytes);
      json["zstdLevel"] = report.size->zstdLevel;
    }
  }
  if (report.encodeSeconds > 0.0)
    json["encodeSeconds"] = report.encodeSeconds;
  return json;
}

std::string reportToText(const CompressionReport& report) {
  std::string text;
  if (report.format)
    text += "format: " + std::string(textureFormatInfo(*report.format).label) + "\n";
  text += "PSNR: " + decibelText(report.image.psnr) + " (";
  for (std::size_t c = 0; c < report.image.channels.size(); ++c) {
    text += std::string(c ? ", " : "") + kChannelNames[c] + " " +
            decibelText(report.image.channels[c].psnr);
  }
  text += ")\n";
  text += format("FLIP: %.4f (95th percentile %.4f; 0 identical, 1 as different as images get)\n",
                 report.flip, report.flipP95);
  text += format("SSIM: %.4f\nmax error: %.4f (%.1f/255)\n", report.image.ssim,
                 report.image.maxError, report.image.maxError * 255.0);
  if (report.normal) {
    text += format("angular error: mean %.3f deg, p99 %.3f deg, max %.2f deg, %.2f%% above 2 deg\n",
                   report.normal->meanDegrees, report.normal->p99Degrees, report.normal->maxDegrees,
                   report.normal->shareAbove2Degrees * 100.0);
  }
  if (report.height) {
    text += format(
        "parallax shift at height scale %.3f (45 deg view): mean %.3f, p99 %.3f, "
        "max %.3f texels\n",
        report.heightScale, report.height->meanTexels, report.height->p99Texels,
        report.height->maxTexels);
  }
  if (report.hdr) {
    text +=
        "exposure PSNR: " + decibelText(report.hdr->exposurePsnr) +
        format(" (stops %+.0f..%+.0f); mean log2 error %.4f stops\n", double(report.hdr->firstStop),
               double(report.hdr->lastStop), report.hdr->meanLog2Error);
  }
  if (report.size) {
    text += format(
        "size: %.0f bytes, %.2f bits per pixel, %.1f:1 against RGBA8, %.1f:1 "
        "against the source\n",
        double(report.size->bytes), report.size->bitsPerPixel, report.size->ratioToRgba8,
        report.size->ratioToSource);
    if (report.size->ktx2Bytes > 0) {
      const double share = 100.0 * double(report.size->ktx2Bytes) / double(report.size->bytes);
      text += report.size->zstdLevel > 0
                  ? format(
                        "on disk: %.0f bytes as KTX2 with Zstandard level %d (%.0f%% of the "
                        "blocks)\n",
                        double(report.size->ktx2Bytes), report.size->zstdLevel, share)
                  : format("on disk: %.0f bytes as KTX2\n", double(report.size->ktx2Bytes));
    }
  }
  if (report.encodeSeconds > 0.0)
    text += format("encoded in %.2f s\n", report.encodeSeconds);
  return text;
}

}  // namespace relief::core::inline compression
