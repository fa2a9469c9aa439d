// EnvironmentMaps; see EnvironmentMaps.h.
#include "core/shading/EnvironmentMaps.h"

#include "core/base/ParallelFor.h"
#include "core/compression/Compressor.h"
#include "core/compression/TextureFile.h"
#include "core/generators/ImageFilters.h"
#include "core/image/ImageIO.h"
#include "core/shading/Brdf.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <list>
#include <map>
#include <mutex>

namespace relief::core::inline shading {
namespace {

struct BuiltInInfo {
  BuiltInEnvironment environment;
  std::string_view name;
  std::string_view label;
  int height;  // rows made: enough for the sharpest feature (the soft boxes' edges)
};

constexpr std::array kBuiltIns = {
    BuiltInInfo{BuiltInEnvironment::Studio, "studio", "Studio (soft boxes)", 512},
    BuiltInInfo{BuiltInEnvironment::Sky, "sky", "Overcast sky", 256},
    BuiltInInfo{BuiltInEnvironment::Uniform, "uniform", "Uniform white", 32},
};
constexpr std::array kBuiltInList = {BuiltInEnvironment::Studio, BuiltInEnvironment::Sky,
                                     BuiltInEnvironment::Uniform};

// A rectangular soft box in (azimuth, elevation), its edges faded over `edgeDeg`. Azimuth is
// measured as equirectUv's u is: 0 toward -Z, 90 toward +X, +-180 toward +Z (behind the default
// camera, so boxes there are what a surface facing the camera reflects).
struct SoftBox {
  float azimuthDeg;
  float elevationDeg;
  float halfWidthDeg;
  float halfHeightDeg;
  float radiance;
};

float boxWeight(const SoftBox& box, float azimuthDeg, float elevationDeg) {
  constexpr float kEdgeDeg = 1.5f;
  const float da = std::remainder(azimuthDeg - box.azimuthDeg, 360.0f);
  const float de = elevationDeg - box.elevationDeg;
  const auto inside = [](float distance, float half) {
    const float t = std::clamp((half - std::abs(distance)) / kEdgeDeg + 0.5f, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
  };
  return inside(da, box.halfWidthDeg) * inside(de, box.halfHeightDeg);
}

// Dark grey walls brightening toward the ceiling, a darker floor, and three soft boxes: the key
// near the default light (azimuth 75 from +Z toward +X, 35 up), a tall fill strip on the other
// side, and a top light. A white diffuse surface facing the key receives about 0.3 of the
// default directional light's irradiance from it, and about 0.15 from the walls: a studio's
// fill, not a second sun.
glm::vec3 studioRadiance(const glm::vec3& d) {
  static constexpr std::array kBoxes = {
      SoftBox{105.0f, 35.0f, 15.0f, 12.0f, 6.0f},  // key, front right
      SoftBox{-110.0f, 20.0f, 5.0f, 25.0f, 2.5f},  // fill strip, front left
      SoftBox{0.0f, 72.0f, 22.0f, 10.0f, 3.0f},    // top, over the back
  };
  const float elevationDeg = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
  const float azimuthDeg = glm::degrees(std::atan2(d.x, -d.z));
  float grey = d.y >= 0.0f ? 0.1f + 0.1f * d.y : 0.04f + 0.02f * (1.0f + d.y);
  for (const SoftBox& box : kBoxes)
    grey += box.radiance * boxWeight(box, azimuthDeg, elevationDeg);
  return glm::vec3(grey);
}

// The CIE standard overcast sky (Moon and Spencer 1942; CIE S 011/E:2003 type 1): radiance
// Lz (1 + 2 cos theta) / 3 at zenith angle theta, a third of the zenith's at the horizon, with a
// cool tint. Below the horizon a diffuse ground of albedo 0.2 lit by that sky: its irradiance is
// 7 pi Lz / 9, so its radiance is 0.2 * 7 Lz / 9. The horizon is blended over a degree.
glm::vec3 skyRadiance(const glm::vec3& d) {
  constexpr float kZenith = 1.0f;
  const glm::vec3 skyTint(0.93f, 0.97f, 1.06f);
  const glm::vec3 groundTint(1.0f, 0.97f, 0.92f);
  const glm::vec3 sky = skyTint * (kZenith * (1.0f + 2.0f * std::max(d.y, 0.0f)) / 3.0f);
  const glm::vec3 ground = groundTint * (0.2f * 7.0f * kZenith / 9.0f);
  const float t = std::clamp(d.y / std::sin(glm::radians(1.0f)) * 0.5f + 0.5f, 0.0f, 1.0f);
  return ground + (sky - ground) * t;
}

Image makeEquirect(int height, glm::vec3 (*radiance)(const glm::vec3&)) {
  const int width = 2 * height;
  Image image(width, height, 4);
  parallelFor(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const glm::vec2 uv((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height));
      const glm::vec3 value = radiance(equirectDirection(uv));
      float* p = image.pixel(x, y);
      p[0] = value.r;
      p[1] = value.g;
      p[2] = value.b;
      p[3] = 1.0f;
    }
  });
  return image;
}

// Four channels of finite, non-negative radiance from whatever the file held.
Image toRadiance(const Image& loaded) {
  Image image(loaded.width(), loaded.height(), 4);
  const int channels = loaded.channels();
  for (int y = 0; y < loaded.height(); ++y) {
    for (int x = 0; x < loaded.width(); ++x) {
      const float* source = loaded.pixel(x, y);
      float* p = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        const float value = source[channels >= 3 ? c : 0];
        p[c] = std::isfinite(value) ? std::max(value, 0.0f) : 0.0f;
      }
      p[3] = 1.0f;
    }
  }
  return image;
}

// A file is identified by its path, size and modification time: an edited file loads again.
struct FileStamp {
  std::uintmax_t size = 0;
  std::filesystem::file_time_type modified;
  bool operator==(const FileStamp&) const = default;
};

std::optional<FileStamp> stampOf(const std::string& path) {
  std::error_code error;
  FileStamp stamp;
  stamp.size = std::filesystem::file_size(path, error);
  if (error)
    return std::nullopt;
  stamp.modified = std::filesystem::last_write_time(path, error);
  if (error)
    return std::nullopt;
  return stamp;
}

}  // namespace

std::span<const BuiltInEnvironment> allBuiltInEnvironments() {
  return kBuiltInList;
}

std::string_view builtInEnvironmentName(BuiltInEnvironment environment) {
  return kBuiltIns[std::size_t(environment)].name;
}

std::string_view builtInEnvironmentLabel(BuiltInEnvironment environment) {
  return kBuiltIns[std::size_t(environment)].label;
}

std::optional<BuiltInEnvironment> findBuiltInEnvironment(std::string_view name) {
  for (const BuiltInInfo& info : kBuiltIns) {
    if (info.name == name)
      return info.environment;
  }
  return std::nullopt;
}

glm::vec2 equirectUv(const glm::vec3& direction) {
  const glm::vec3 d = glm::normalize(direction);
  return glm::vec2(std::atan2(d.x, -d.z) / (2.0f * kPi) + 0.5f,
                   std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi);
}

glm::vec3 equirectDirection(const glm::vec2& uv) {
  const float azimuth = (uv.x - 0.5f) * 2.0f * kPi;
  const float polar = uv.y * kPi;
  return glm::vec3(std::sin(polar) * std::sin(azimuth), std::cos(polar),
                   -std::sin(polar) * std::cos(azimuth));
}

Image makeBuiltInEnvironment(BuiltInEnvironment environment, int height) {
  switch (environment) {
    case BuiltInEnvironment::Studio:
      return makeEquirect(height, studioRadiance);
    case BuiltInEnvironment::Sky:
      return makeEquirect(height, skyRadiance);
    case BuiltInEnvironment::Uniform:
      break;
  }
  return makeEquirect(height, [](const glm::vec3&) { return glm::vec3(1.0f); });
}

namespace {

// A BC6H texture (KTX2 or DDS) as radiance: level 0 decoded. Other block formats hold 0..1
// and are refused as 8-bit files are.
Result<Image> loadCompressedEnvironment(const std::string& path) {
  Result<CompressedTexture> texture = loadCompressedTexture(path);
  if (!texture)
    return makeError(texture.error());
  const TextureFormatInfo& info = textureFormatInfo(texture->format);
  if (!isHalfFloatFormat(texture->format)) {
    return makeError(path + ": " + std::string(info.label) +
                     " holds no radiance above 1; an environment texture must be BC6H");
  }
  const CompressedLevel& base = texture->levels.front();
  if (std::abs(base.width - 2 * base.height) > 2) {
    return makeError(path + ": " + std::to_string(base.width) + "x" + std::to_string(base.height) +
                     " is not an equirectangular (latitude-longitude) map, which is twice as "
                     "wide as it is tall");
  }
  Result<Image> decoded = decodeLevel(texture.value(), 0);
  if (!decoded)
    return makeError(path + ": " + decoded.error());
  return toRadiance(decoded.value());
}

}  // namespace

Result<Image> loadEnvironmentFile(const std::string& path) {
  if (containerForPath(path)) {
    Result<Image> radiance = loadCompressedEnvironment(path);
    if (radiance && radiance->width() > kEnvironmentWorkingWidth)
      return resizeImage(radiance.value(), kEnvironmentWorkingWidth, kEnvironmentWorkingWidth / 2);
    return radiance;
  }
  const Result<ImageFileInfo> info = readImageInfo(path);
  if (!info)
    return makeError(info.error());
  const int width = info.value().width;
  const int height = info.value().height;
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (!info.value().isFloat) {
    return makeError(path + ": " + std::to_string(info.value().bitsPerChannel) + "-bit " +
                     info.value().formatName +
                     " holds no radiance above 1; an environment must be an EXR or Radiance HDR "
                     "file");
  }
  if (width > kMaxEnvironmentWidth) {
    return makeError(path + ": " + size + " is wider than the " +
                     std::to_string(kMaxEnvironmentWidth) + " texels an environment may have");
  }
  // Equirectangular maps are 2:1; allow a texel of rounding either way.
  if (std::abs(width - 2 * height) > 2) {
    return makeError(path + ": " + size +
                     " is not an equirectangular (latitude-longitude) map, which is twice as "
                     "wide as it is tall");
  }
  Result<Image> loaded = loadImage(path);
  if (!loaded)
    return makeError(loaded.error());
  Image radiance = toRadiance(loaded.value());
  if (radiance.width() > kEnvironmentWorkingWidth) {
    radiance = resizeImage(radiance, kEnvironmentWorkingWidth, kEnvironmentWorkingWidth / 2);
  }
  return radiance;
}

Result<std::shared_ptr<const Image>> environmentRadiance(const std::string& source) {
  struct CachedFile {
    std::string path;
    FileStamp stamp;
    std::shared_ptr<const Image> image;
  };
  constexpr std::size_t kCachedFiles = 3;
  static std::mutex mutex;
  static std::map<BuiltInEnvironment, std::shared_ptr<const Image>> builtIns;
  static std::list<CachedFile> files;  // most recently used first

  if (const std::optional<BuiltInEnvironment> builtIn = findBuiltInEnvironment(source)) {
    const std::lock_guard lock(mutex);
    std::shared_ptr<const Image>& image = builtIns[*builtIn];
    if (!image) {
      image = std::make_shared<const Image>(
          makeBuiltInEnvironment(*builtIn, kBuiltIns[std::size_t(*builtIn)].height));
    }
    return image;
  }
  const std::optional<FileStamp> stamp = stampOf(source);
  {
    const std::lock_guard lock(mutex);
    for (auto it = files.begin(); it != files.end(); ++it) {
      if (it->path == source && stamp && it->stamp == *stamp) {
        files.splice(files.begin(), files, it);
        return files.front().image;
      }
    }
  }
  // Loaded outside the lock: a slow file does not hold up built-ins or other files.
  Result<Image> loaded = loadEnvironmentFile(source);
  if (!loaded)
    return makeError(loaded.error());
  auto image = std::make_shared<const Image>(std::move(loaded.value()));
  const std::lock_guard lock(mutex);
  files.remove_if([&](const CachedFile& file) { return file.path == source; });
  files.push_front(CachedFile{source, stamp.value_or(FileStamp{}), image});
  if (files.size() > kCachedFiles)
    files.pop_back();
  return image;
}

}  // namespace relief::core::inline shading
