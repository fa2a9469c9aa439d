// Technique names; see Technique.h.
#include "core/material/Technique.h"

#include <array>

namespace relief::core::inline material {
namespace {

struct TechniqueInfo {
  Technique technique;
  std::string_view name;
  std::string_view label;
  std::string_view shaderDefine;  // selects its code in shaders/include/parallax.glsl
  bool marching;                  // marches along the view ray (see isMarchingTechnique)
  bool exact;                     // walks to the exact intersection (see isExactTracing)
};

constexpr std::array kTechniques = {
    TechniqueInfo{Technique::Normal, "normal", "Normal mapping", "TECHNIQUE_NORMAL", false, false},
    TechniqueInfo{Technique::Parallax, "parallax", "Parallax (Kaneko)", "TECHNIQUE_PARALLAX", false,
                  false},
    TechniqueInfo{Technique::ParallaxLimited, "parallax-limited",
                  "Parallax, offset limited (Welsh)", "TECHNIQUE_PARALLAX_LIMITED", false, false},
    TechniqueInfo{Technique::Steep, "steep", "Steep parallax", "TECHNIQUE_STEEP", true, false},
    TechniqueInfo{Technique::Pom, "pom", "Parallax occlusion mapping", "TECHNIQUE_POM", true,
                  false},
    TechniqueInfo{Technique::Relief, "relief", "Relief mapping (binary refinement)",
                  "TECHNIQUE_RELIEF", true, false},
    TechniqueInfo{Technique::Quadtree, "quadtree", "Quadtree (maximum mipmap, exact)",
                  "TECHNIQUE_QUADTREE", true, true},
    TechniqueInfo{Technique::Cone, "cone", "Cone stepping (exact)", "TECHNIQUE_CONE", true, true},
    TechniqueInfo{Technique::Displacement, "displacement", "Displacement (tessellated geometry)",
                  "TECHNIQUE_DISPLACEMENT", false, false},
};

constexpr bool rowsInEnumOrder() {
  for (std::size_t i = 0; i < kTechniques.size(); ++i) {
    if (std::size_t(kTechniques[i].technique) != i)
      return false;
  }
  return true;
}
static_assert(kTechniques.size() == kTechniqueCount, "one row per technique");
static_assert(rowsInEnumOrder(), "the functions below index the rows by technique");

constexpr std::array<Technique, kTechniques.size()> techniqueList() {
  std::array<Technique, kTechniques.size()> list{};
  for (std::size_t i = 0; i < kTechniques.size(); ++i)
    list[i] = kTechniques[i].technique;
  return list;
}
constexpr std::array kTechniqueList = techniqueList();

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

std::string_view techniqueShaderDefine(Technique technique) {
  return kTechniques[std::size_t(technique)].shaderDefine;
}

bool isMarchingTechnique(Technique technique) {
  return kTechniques[std::size_t(technique)].marching;
}

bool isExactTracing(Technique technique) {
  return kTechniques[std::size_t(technique)].exact;
}

bool supportsHexTiling(Technique technique) {
  return !isExactTracing(technique) && technique != Technique::Displacement;
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
