// bench-compress: encoding speed and quality per format and quality level, first on real
// photographs (scikit-image's, from Debian's python3-skimage: synthetic maps flatter encoders),
// with astcenc 4x4 (fast, medium, thorough presets through the library Relief links) as the
// peer BC7 is raced against at the same 8 bits per texel; then on the bricks sample resized to
// 2048^2 (colour map and normal map), with libsquish's own CompressImage (cluster fit, DXT1) on
// the same colour map as the reference row, measured in the same run. Then the target:
// BC4 and BC5 of 4096^2 maps in at most 1 s.
//
// Quality: PSNR (dB) for colour, mean angular error (degrees) for normals, PSNR for height.
// Run: build/release/tools/bench-compress [--quick] [--photos]   (--quick skips quality
// "best", --photos stops after the photographs)
//      build/release/tools/bench-compress --squish FILE.png   (only libsquish's cluster-fit BC1
// of that image: "SECONDS PSNR" on one line, for tools/bench-cli's whole-process BC1 row)
#include "core/compression/BlockCodecs.h"
#include "core/compression/CompressionMetrics.h"
#include "core/compression/Compressor.h"
#include "core/generators/ImageFilters.h"
#include "core/image/ImageIO.h"

#include <squish.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#ifndef RELIEF_SOURCE_DIR
#error "RELIEF_SOURCE_DIR must point at the source tree (for the samples)"
#endif

namespace {

using namespace relief;

double secondsOf(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

core::Image load(const char* file, int size) {
  auto image = core::loadImage(std::string(RELIEF_SOURCE_DIR "/samples/bricks/") + file);
  if (!image) {
    std::fprintf(stderr, "bench-compress: %s\n", image.error().c_str());
    std::exit(1);
  }
  return core::resizeImage(image.value(), size, size);
}

void printRow(const char* map, const std::string& format, const char* quality, double seconds,
              double megapixels, const std::string& metric, const char* note = "") {
  std::printf("| %-6s | %-17s | %-6s | %8.2f | %8.2f | %-22s | %s\n", map, format.c_str(), quality,
              seconds, megapixels / seconds, metric.c_str(), note);
  std::fflush(stdout);
}

std::string metricText(const core::Image& map, core::MapSlot slot,
                       const core::CompressedTexture& texture) {
  const core::Image decoded = core::decodeAsMap(texture).value();
  char text[64];
  if (slot == core::MapSlot::Normal) {
    std::snprintf(text, sizeof text, "mean %.3f deg",
                  core::measureNormalError(map, decoded).meanDegrees);
  } else {
    std::snprintf(text, sizeof text, "PSNR %.2f dB", core::measureImageError(map, decoded).psnr);
  }
  return text;
}

void benchFormat(const char* label, const core::Image& map, core::MapSlot slot,
                 core::TextureFormat format, core::CompressionQuality quality) {
  core::Result<core::CompressedTexture> texture = core::Error{""};
  const double seconds = secondsOf([&] {
    texture = core::compressMap(map, slot, {format, quality, false});
  });
  if (!texture) {
    std::fprintf(stderr, "bench-compress: %s\n", texture.error().c_str());
    return;
  }
  printRow(label, std::string(core::textureFormatInfo(format).name),
           core::compressionQualityName(quality).data(), seconds, double(map.pixelCount()) / 1e6,
           metricText(map, slot, texture.value()));
}

// scikit-image's colour photographs (python3-skimage; tools/install-deps.sh --bench).
constexpr const char* kPhotoFolder = "/usr/lib/python3/dist-packages/skimage/data/";
constexpr const char* kPhotos[] = {"astronaut.png", "coffee.png", "chelsea.png", "rocket.jpg",
                                   "motorcycle_left.png"};

struct PhotoResult {
  double seconds = 0.0;  // all photos, the fastest of the runs
  double meanPsnr = 0.0;
  std::string psnrs;  // per photo
};

// Every photo compressed `runs` times (the fastest time counts: the machine is shared).
PhotoResult benchPhotos(const std::vector<core::Image>& photos, core::TextureFormat format,
                        core::CompressionQuality quality, int runs) {
  PhotoResult result;
  for (const core::Image& photo : photos) {
    core::Result<core::CompressedTexture> texture = core::Error{""};
    double fastest = 1e30;
    for (int run = 0; run < runs; ++run) {
      fastest = std::min(
          fastest, secondsOf([&] {
            texture = core::compressMap(photo, core::MapSlot::Color, {format, quality, false});
          }));
    }
    result.seconds += fastest;
    const double psnr =
        core::measureImageError(photo, core::decodeAsMap(texture.value()).value()).psnr;
    result.meanPsnr += psnr / double(photos.size());
    char text[16];
    std::snprintf(text, sizeof text, "%s%.2f", result.psnrs.empty() ? "" : " ", psnr);
    result.psnrs += text;
  }
  return result;
}

// libsquish's BC1 of an image: CompressImage over the whole RGBA8 image (OpenMP-threaded in
// Debian's build), as an application calling the library would; `metric` null is uniform.
core::CompressedTexture squishBc1(const core::Image& colour, int fit, float* metric,
                                  double& seconds) {
  const int width = colour.width(), height = colour.height();
  std::vector<squish::u8> rgba(std::size_t(width) * std::size_t(height) * 4);
  for (std::size_t p = 0; p < colour.pixelCount(); ++p) {
    for (int c = 0; c < 4; ++c) {
      const float v =
          c < 3 ? colour.data()[p * std::size_t(colour.channels()) + std::size_t(c)] : 1.0f;
      rgba[p * 4 + std::size_t(c)] = squish::u8(std::lround(v * 255.0f));
    }
  }
  core::CompressedTexture texture;
  texture.format = core::TextureFormat::Bc1;
  texture.srgb = true;
  texture.sourceChannels = 3;
  texture.levels.push_back({width, height, {}});
  texture.levels[0].data.resize(core::compressedLevelSize(core::TextureFormat::Bc1, width, height));
  seconds = secondsOf([&] {
    squish::CompressImage(rgba.data(), width, height, texture.levels[0].data.data(),
                          squish::kDxt1 | fit, metric);
  });
  return texture;
}

// The photographs (scikit-image's data folder), their total size and names; empty when one
// cannot be read (the message says what to install).
std::vector<core::Image> loadPhotographs(double& megapixels, std::string& names) {
  std::vector<core::Image> photos;
  for (const char* name : kPhotos) {
    auto image = core::loadImage(std::string(kPhotoFolder) + name);
    if (!image) {
      std::printf("photographs: %s (install python3-skimage: tools/install-deps.sh --bench)\n\n",
                  image.error().c_str());
      return {};
    }
    megapixels += double(image.value().pixelCount()) / 1e6;
    names += std::string(names.empty() ? "" : ", ") + name;
    photos.push_back(std::move(image).value());
  }
  return photos;
}

// libsquish's BC1 with uniform weights (its default, and what PSNR measures), range and
// cluster fit, printed as table rows: the reference for our BC1. Returns cluster fit's total
// seconds and mean PSNR.
std::pair<double, double> benchSquishOnPhotos(const std::vector<core::Image>& photos,
                                              double megapixels) {
  double squishSeconds = 0.0, squishPsnr = 0.0;
  for (const auto& [fit, name] : {std::pair{int(squish::kColourRangeFit), "range fit"},
                                  std::pair{int(squish::kColourClusterFit), "cluster fit"}}) {
    double total = 0.0, mean = 0.0;
    std::string psnrs;
    for (const core::Image& photo : photos) {
      double fastest = 1e30, seconds = 0.0;
      core::CompressedTexture texture;
      for (int run = 0; run < 3; ++run) {
        texture = squishBc1(photo, fit, nullptr, seconds);
        fastest = std::min(fastest, seconds);
      }
      total += fastest;
      const double psnr = core::measureImageError(photo, core::decodeAsMap(texture).value()).psnr;
      mean += psnr / double(photos.size());
      char text[16];
      std::snprintf(text, sizeof text, "%s%.2f", psnrs.empty() ? "" : " ", psnr);
      psnrs += text;
    }
    std::printf("| squish   | %-6s | %8.3f | %8.2f | %6.2f dB | %s (libsquish BC1 %s)\n",
                fit == squish::kColourClusterFit ? "normal" : "fast", total, megapixels / total,
                mean, psnrs.c_str(), name);
    if (fit == squish::kColourClusterFit) {
      squishSeconds = total;
      squishPsnr = mean;
    }
  }
  return {squishSeconds, squishPsnr};
}

// BC7 against astcenc 4x4 (the same 8 bits per texel) and the other colour formats, on real
// photographs. Returns whether the targets are met: BC7 normal within 0.5 dB of astcenc
// -medium in no more of its time, best at or above -medium; BC1 normal within 0.05 dB of
// libsquish's cluster fit in a tenth of its time; ETC2 RGB 0.5 dB above ETC1.
bool benchPhotographs(const std::vector<core::CompressionQuality>& qualities) {
  double megapixels = 0.0;
  std::string names;
  const std::vector<core::Image> photos = loadPhotographs(megapixels, names);
  if (photos.empty())
    return false;
  std::printf(
      "bench-compress: %zu photographs (%s; %.2f Mpixels), %u threads, fastest of 3 runs\n\n",
      photos.size(), names.c_str(), megapixels, std::thread::hardware_concurrency());
  std::printf("| format   | qual.  |    s     |  MPix/s  | mean PSNR | PSNR per photo\n");
  std::printf("|----------|--------|----------|----------|-----------|---------------\n");
  const auto [squishSeconds, squishPsnr] = benchSquishOnPhotos(photos, megapixels);
  double astcMediumSeconds = 0.0, astcMediumPsnr = 0.0, bc7NormalSeconds = 0.0, bc7NormalPsnr = 0.0,
         bc7BestPsnr = -1.0, bc1NormalSeconds = 0.0, bc1NormalPsnr = 0.0, etc1Psnr = 0.0,
         etc2Psnr = 0.0;
  for (core::TextureFormat format :
       {core::TextureFormat::Astc4x4, core::TextureFormat::Bc7, core::TextureFormat::Bc1,
        core::TextureFormat::Etc1, core::TextureFormat::Etc2}) {
    for (core::CompressionQuality quality : qualities) {
      const PhotoResult result = benchPhotos(photos, format, quality, 3);
      std::printf("| %-8s | %-6s | %8.3f | %8.2f | %6.2f dB | %s\n",
                  core::textureFormatInfo(format).name.data(),
                  core::compressionQualityName(quality).data(), result.seconds,
                  megapixels / result.seconds, result.meanPsnr, result.psnrs.c_str());
      std::fflush(stdout);
      if (quality == core::CompressionQuality::Normal && format == core::TextureFormat::Astc4x4) {
        astcMediumSeconds = result.seconds;
        astcMediumPsnr = result.meanPsnr;
      }
      if (format == core::TextureFormat::Bc7 && quality == core::CompressionQuality::Normal) {
        bc7NormalSeconds = result.seconds;
        bc7NormalPsnr = result.meanPsnr;
      }
      if (format == core::TextureFormat::Bc7 && quality == core::CompressionQuality::Best)
        bc7BestPsnr = result.meanPsnr;
      if (format == core::TextureFormat::Bc1 && quality == core::CompressionQuality::Normal) {
        bc1NormalSeconds = result.seconds;
        bc1NormalPsnr = result.meanPsnr;
      }
      if (format == core::TextureFormat::Etc1 && quality == core::CompressionQuality::Normal)
        etc1Psnr = result.meanPsnr;
      if (format == core::TextureFormat::Etc2 && quality == core::CompressionQuality::Normal)
        etc2Psnr = result.meanPsnr;
    }
  }
  const bool normalMet =
      bc7NormalPsnr >= astcMediumPsnr - 0.5 && bc7NormalSeconds <= astcMediumSeconds;
  std::printf(
      "\nTarget: BC7 normal within 0.5 dB of astcenc 4x4 -medium in no more time: "
      "%.2f dB in %.3f s against %.2f dB in %.3f s: %s\n",
      bc7NormalPsnr, bc7NormalSeconds, astcMediumPsnr, astcMediumSeconds,
      normalMet ? "met" : "MISSED");
  const bool bc1Met =
      bc1NormalPsnr >= squishPsnr - 0.05 && bc1NormalSeconds * 10.0 <= squishSeconds;
  std::printf(
      "Target: BC1 normal at least libsquish cluster fit's PSNR - 0.05 dB in at most 1/10 "
      "of its time: %.2f dB in %.3f s against %.2f dB in %.3f s (%.1fx faster): %s\n",
      bc1NormalPsnr, bc1NormalSeconds, squishPsnr, squishSeconds,
      squishSeconds / std::max(bc1NormalSeconds, 1e-9), bc1Met ? "met" : "MISSED");
  const bool etc2Met = etc2Psnr >= etc1Psnr + 0.5;
  std::printf(
      "Target: ETC2 RGB normal at least 0.5 dB above ETC1: %.2f dB against %.2f dB "
      "(+%.2f): %s\n",
      etc2Psnr, etc1Psnr, etc2Psnr - etc1Psnr, etc2Met ? "met" : "MISSED");
  bool met = normalMet && bc1Met && etc2Met;
  if (bc7BestPsnr >= 0.0) {
    met = met && bc7BestPsnr >= astcMediumPsnr;
    std::printf("Target: BC7 best at or above astcenc -medium: %.2f dB against %.2f dB: %s\n",
                bc7BestPsnr, astcMediumPsnr, bc7BestPsnr >= astcMediumPsnr ? "met" : "MISSED");
  }
  std::printf("\n");
  return met;
}

// libsquish on its own: CompressImage over the whole RGBA8 image (OpenMP-threaded in Debian's
// build), as an application calling the library would, with its default uniform weights and
// with the luminance weights Relief passes for colour maps. Decoded with our decoder.
void benchSquishReference(const core::Image& colour) {
  float perceptual[3] = {0.2126f, 0.7152f, 0.0722f};
  for (float* metric : {static_cast<float*>(nullptr), perceptual}) {
    double seconds = 0.0;
    const core::CompressedTexture texture =
        squishBc1(colour, squish::kColourClusterFit, metric, seconds);
    printRow("colour", "libsquish BC1 ref", "normal", seconds, double(colour.pixelCount()) / 1e6,
             metricText(colour, core::MapSlot::Color, texture),
             metric ? "squish::CompressImage, luminance weights"
                    : "squish::CompressImage, uniform weights");
  }
}

// EAC R11 against an exhaustive search: every table, multiplier and base (16 x 16 x 256
// candidates, each texel at its nearest value) on a sample of the map's blocks, which is the
// best any EAC encoder can do for those blocks. The ratio of mean squared errors says what the
// fast search gives away. Texel values in R11 units (0..2047).
double exhaustiveEacError(const double target[16]) {
  double best = 1e300;
  for (const auto& table : core::kEacModifiers) {
    for (int multiplier = 0; multiplier < 16; ++multiplier) {
      for (int base = 0; base < 256; ++base) {
        double error = 0.0;
        for (int t = 0; t < 16 && error < best; ++t) {
          double nearest = 1e300;
          for (int modifier : table) {
            const int step = multiplier == 0 ? modifier : modifier * multiplier * 8;
            const double d = std::clamp(base * 8 + 4 + step, 0, 2047) - target[t];
            nearest = std::min(nearest, d * d);
          }
          error += nearest;
        }
        best = std::min(best, error);
      }
    }
  }
  return best;
}

void benchEacAgainstExhaustive(const core::Image& height, core::CompressionQuality quality) {
  constexpr int kSamples = 400;
  double ours = 0.0, exhaustive = 0.0;
  const int blocksX = height.width() / 4, blocksY = height.height() / 4;
  for (int i = 0; i < kSamples; ++i) {
    // Blocks spread over the map (a fixed stride), so flat and busy ones are both sampled.
    const int block = int((std::uint64_t(i) * 2654435761u) % std::uint64_t(blocksX * blocksY));
    const int bx = block % blocksX * 4, by = block / blocksX * 4;
    float values[16], decoded[16];
    double target[16];
    for (int t = 0; t < 16; ++t) {
      values[t] = height.at(bx + t % 4, by + t / 4, 0);
      target[t] = std::clamp(double(values[t]), 0.0, 1.0) * 2047.0;
    }
    std::uint8_t encoded[8];
    core::encodeEacChannel(values, 0xffff, true, quality, encoded);
    core::decodeEacChannel(encoded, true, decoded);
    for (int t = 0; t < 16; ++t) {
      const double d = double(decoded[t]) * 2047.0 - target[t];
      ours += d * d;
    }
    exhaustive += exhaustiveEacError(target);
  }
  std::printf(
      "| height | eac-r11 vs exhaustive | %-6s | MSE %.3f against %.3f (R11 units^2) on %d "
      "blocks: %.1f%% more error than the best possible\n",
      core::compressionQualityName(quality).data(), ours / (16.0 * kSamples),
      exhaustive / (16.0 * kSamples), kSamples, 100.0 * (ours / std::max(exhaustive, 1e-12) - 1.0));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char* argv[]) {
  if (argc == 3 && std::strcmp(argv[1], "--squish") == 0) {
    core::Result<core::Image> image = core::loadImage(argv[2]);
    if (!image) {
      std::fprintf(stderr, "bench-compress: %s\n", image.error().c_str());
      return 1;
    }
    double seconds = 0.0;
    const core::CompressedTexture texture =
        squishBc1(image.value(), squish::kColourClusterFit, nullptr, seconds);
    std::printf("%.3f %.3f\n", seconds,
                core::measureImageError(image.value(), core::decodeAsMap(texture).value()).psnr);
    return 0;
  }
  bool quick = false, photosOnly = false;
  for (int i = 1; i < argc; ++i) {
    quick = quick || std::strcmp(argv[i], "--quick") == 0;
    photosOnly = photosOnly || std::strcmp(argv[i], "--photos") == 0;
  }
  std::vector<core::CompressionQuality> qualities = {core::CompressionQuality::Fast,
                                                     core::CompressionQuality::Normal};
  if (!quick)
    qualities.push_back(core::CompressionQuality::Best);

  bool met = benchPhotographs(qualities);
  if (photosOnly)
    return met ? 0 : 1;

  const core::Image colour = load("bricks_color.png", 2048);
  const core::Image normal = load("bricks_normal.png", 2048);
  std::printf("bench-compress: 2048x2048 bricks colour and normal maps, %u threads\n\n",
              std::thread::hardware_concurrency());
  std::printf(
      "| map    | format            | qual.  |    s     |  MPix/s  | quality                | "
      "note\n");
  std::printf(
      "|--------|-------------------|--------|----------|----------|------------------------|-----"
      "\n");
  benchSquishReference(colour);
  for (core::TextureFormat format : core::formatsForSlot(core::MapSlot::Color)) {
    for (core::CompressionQuality quality : qualities)
      benchFormat("colour", colour, core::MapSlot::Color, format, quality);
  }
  for (core::TextureFormat format : core::formatsForSlot(core::MapSlot::Normal)) {
    for (core::CompressionQuality quality : qualities)
      benchFormat("normal", normal, core::MapSlot::Normal, format, quality);
  }

  // EAC on data maps: the speed and how close the search gets to the best possible blocks.
  const core::Image height = load("bricks_height.png", 2048);
  for (core::CompressionQuality quality : qualities)
    benchFormat("height", height, core::MapSlot::Height, core::TextureFormat::EacR11, quality);
  for (core::CompressionQuality quality : qualities)
    benchEacAgainstExhaustive(height, quality);

  std::printf("\nTarget: BC4 and BC5 of a 4096x4096 map in at most 1 s (quality normal)\n");
  const core::Image height4k = load("bricks_height.png", 4096);
  const core::Image normal4k = load("bricks_normal.png", 4096);
  for (const auto& [map, slot, format] :
       {std::tuple{&height4k, core::MapSlot::Height, core::TextureFormat::Bc4},
        std::tuple{&normal4k, core::MapSlot::Normal, core::TextureFormat::Bc5}}) {
    core::Result<core::CompressedTexture> texture = core::Error{""};
    const double seconds = secondsOf([&] {
      texture = core::compressMap(*map, slot, {format, core::CompressionQuality::Normal, false});
    });
    met = met && seconds <= 1.0;
    printRow(slot == core::MapSlot::Height ? "height" : "normal",
             std::string(core::textureFormatInfo(format).name) + " 4096^2", "normal", seconds,
             double(map->pixelCount()) / 1e6, metricText(*map, slot, texture.value()),
             seconds <= 1.0 ? "<= 1 s: met" : "<= 1 s: MISSED");
  }
  return met ? 0 : 1;
}
