// Technique names; see Technique.h.
#include "core/material/Technique.h"

#include <array>

namespace relief::core::inline material {
namespace {

struct TechniqueInfo {
  Technique technique;
  std::string_view name;
  std::string_view label;
};

constexpr std::array kTechniques = {
    TechniqueInfo{Technique::Normal, "normal", "Normal mapping"},
    TechniqueInfo{Technique::Parallax, "parallax", "Parallax (Kaneko)"},
    TechniqueInfo{Technique::ParallaxLimited, "parallax-limited",
                  "Parallax, offset limited (Welsh)"},
    TechniqueInfo{Technique::Steep, "steep", "Steep parallax"},
    TechniqueInfo{Technique::Pom, "pom", "Parallax occlusion mapping"},
    TechniqueInfo{Technique::Relief, "relief", "Relief mapping (binary refinement)"},
    TechniqueInfo{Technique::Quadtree, "quadtree", "Quadtree (maximum mipmap, exact)"},
    TechniqueInfo{Technique::Cone, "cone", "Cone stepping (exact)"},
    TechniqueInfo{Technique::Displacement, "displacement", "Displacement (tessellated geometry)"},
};

constexpr std::array kTechniqueList = {
    Technique::Normal,   Technique::Parallax, Technique::ParallaxLimited,
    Technique::Steep,    Technique::Pom,      Technique::Relief,
    Technique::Quadtree, Technique::Cone,     Technique::Displacement};

}  // namespace

std::span<const Technique> allTechniques() {
  return kTechniqueList;
}

std::string_view techniqueName(Technique technique) {
  return kTechniques[std::size_t(technique)].name;
}

std::string_view techniqueLabel(Technique technique) {
  return kTechniques[std::size_t(technique)].label;
}

bool isMarchingTechnique(Technique technique) {
  return technique == Technique::Steep || technique == Technique::Pom ||
         technique == Technique::Relief || isExactTracing(technique);
}

bool isExactTracing(Technique technique) {
  return technique == Technique::Quadtree || technique == Technique::Cone;
}

bool isOccludingRelief(Technique technique) {
  return isMarchingTechnique(technique) || technique == Technique::Displacement;
}

std::optional<Technique> findTechnique(std::string_view name) {
  for (const TechniqueInfo& info : kTechniques) {
    if (info.name == name)
      return info.technique;
  }
  return std::nullopt;
}

}  // namespace relief::core::inline material
