// The rendering techniques a material can use. The names are the CLI's --technique values
// and the presets' "technique" key.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace relief::core {

enum class Technique {
  Normal,  // per-pixel normal mapping in tangent space (reference 004)
};

std::span<const Technique> allTechniques();
std::string_view techniqueName(Technique technique);
std::string_view techniqueLabel(Technique technique);
std::optional<Technique> findTechnique(std::string_view name);

}  // namespace relief::core
