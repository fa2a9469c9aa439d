// Environment; see Environment.h.
#include "core/view/Environment.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include <array>

namespace relief::core::inline view {
namespace {

struct BackgroundInfo {
  Background background;
  std::string_view name;
  std::string_view label;
};

constexpr std::array kBackgrounds = {
    BackgroundInfo{Background::Color, "color", "Plain colour"},
    BackgroundInfo{Background::Environment, "environment", "Environment"},
    BackgroundInfo{Background::Blurred, "blurred", "Environment, blurred"},
};
constexpr std::array kBackgroundList = {Background::Color, Background::Environment,
                                        Background::Blurred};

}  // namespace

glm::mat3 Environment::worldToEnvironment() const {
  return glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(rotationDeg), glm::vec3(0, 1, 0)));
}

std::span<const Background> allBackgrounds() {
  return kBackgroundList;
}

std::string_view backgroundName(Background background) {
  return kBackgrounds[std::size_t(background)].name;
}

std::string_view backgroundLabel(Background background) {
  return kBackgrounds[std::size_t(background)].label;
}

std::optional<Background> findBackground(std::string_view name) {
  for (const BackgroundInfo& info : kBackgrounds) {
    if (info.name == name)
      return info.background;
  }
  return std::nullopt;
}

}  // namespace relief::core::inline view
