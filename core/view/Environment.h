// Environment: the image-based light of pbr shading and what the background shows. The light
// comes from an equirectangular radiance map, one of the built-ins made in code (a studio with
// soft boxes, an overcast sky, a uniform white; core/shading/EnvironmentMaps.h) or an EXR or
// Radiance HDR file, scaled by an intensity and turned about the vertical axis. Classic shading
// keeps its ambient term and uses the environment only for the background.
#pragma once

#include <glm/mat3x3.hpp>

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace relief::core::inline view {

enum class Background {
  Color,        // the quiet dark gradient: neutral, it does not tint judgement of colour
  Environment,  // the environment as the material's reflections see it (mirror-sharp)
  Blurred,      // the environment prefiltered as a rough surface sees it
};

struct Environment {
  static constexpr float kMaxIntensity = 16.0f;
  std::string source = "studio";  // a built-in's name, or an EXR/HDR file's path
  float intensity = 1.0f;         // factor on the radiance (0..kMaxIntensity)
  float rotationDeg = 0.0f;       // about +Y; positive turns the environment toward +X
  Background background = Background::Color;

  // Turns a world direction into the environment's: the rotation about +Y by rotationDeg, so
  // what the unrotated map shows toward -Z appears toward +X at 90 degrees.
  glm::mat3 worldToEnvironment() const;
  bool operator==(const Environment&) const = default;
};

std::span<const Background> allBackgrounds();
std::string_view backgroundName(Background background);   // "color", "environment", "blurred"
std::string_view backgroundLabel(Background background);  // "Plain colour", ...
std::optional<Background> findBackground(std::string_view name);

}  // namespace relief::core::inline view
