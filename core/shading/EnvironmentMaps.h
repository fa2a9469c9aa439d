// Environment maps: the equirectangular radiance images image-based light comes from. Row 0 is
// the zenith (+Y), the last row the nadir; the centre column looks toward -Z, the direction the
// default camera looks in, so the middle of the image is what is seen behind the material.
// Direction d maps to u = atan2(d.x, -d.z) / 2pi + 0.5, v = acos(d.y) / pi (equirectUv).
//
// Built-ins are made in code, so nothing is downloaded: a studio (dark walls, three soft boxes),
// an overcast sky (the CIE standard overcast sky over a grey ground) and a uniform white of
// radiance 1 (the white furnace). Files are EXR or Radiance HDR, through OpenImageIO, or BC6H
// textures (the environment as it ships compressed: EnvironmentPanel saves one).
#pragma once

#include "core/base/Result.h"
#include "core/image/Image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace relief::core::inline shading {

enum class BuiltInEnvironment { Studio, Sky, Uniform };

std::span<const BuiltInEnvironment> allBuiltInEnvironments();
std::string_view builtInEnvironmentName(BuiltInEnvironment environment);   // "studio", ...
std::string_view builtInEnvironmentLabel(BuiltInEnvironment environment);  // "Studio", ...
std::optional<BuiltInEnvironment> findBuiltInEnvironment(std::string_view name);

// Environment files wider than this are refused (the header is read first, so an enormous file
// costs nothing); files wider than kEnvironmentWorkingWidth are resized to it on load: the
// prefiltered light needs far less, and the mirror-sharp background gains little beyond it.
constexpr int kMaxEnvironmentWidth = 16384;
constexpr int kEnvironmentWorkingWidth = 4096;

// Texture coordinates of a direction (unit or not) in an equirectangular map, and back.
glm::vec2 equirectUv(const glm::vec3& direction);
glm::vec3 equirectDirection(const glm::vec2& uv);

// The built-in at `height` rows (twice as many columns): four channels, linear radiance.
Image makeBuiltInEnvironment(BuiltInEnvironment environment, int height);

// An EXR or Radiance HDR file, or a BC6H texture (KTX2 or DDS: level 0, as a GPU would light
// with it), as four channels of linear radiance: refused with a message naming the file when it
// cannot be read, is not floating point (an 8-bit image or block format holds no radiance above
// 1), is not twice as wide as it is tall, or is wider than kMaxEnvironmentWidth. Values that are
// not finite or are negative become 0; grey files become RGB.
Result<Image> loadEnvironmentFile(const std::string& path);

// A built-in's name or a file's path to its radiance image. Kept for the process (built-ins, and
// the last few files while they stay unchanged on disk), so asking again costs nothing: the
// editor asks off the GUI thread first, then the renderer asks again when it draws. Thread-safe.
Result<std::shared_ptr<const Image>> environmentRadiance(const std::string& source);

}  // namespace relief::core::inline shading
