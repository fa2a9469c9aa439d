// EngineConversion; see EngineConversion.h.
#include "core/exporters/EngineConversion.h"

#include "core/generators/ChannelPacking.h"
#include "core/shading/Brdf.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace relief::core::inline exporters {
namespace {

Image withGreenInverted(const Image& normals) {
  Image flipped = normals;
  for (std::size_t p = 0; p < flipped.pixelCount(); ++p) {
    float& green = flipped.data()[p * std::size_t(flipped.channels()) + 1];
    green = 1.0f - green;
  }
  return flipped;
}

}  // namespace

bool shadesPbr(const Material& material) {
  return ShadingModel(int(material.parameter(ParamId::Shading))) == ShadingModel::Pbr;
}

double exportedMetallic(const Material& material) {
  return shadesPbr(material) ? material.parameter(ParamId::Metallic) : 0.0;
}

double exportedRoughness(const Material& material) {
  return shadesPbr(material) ? material.parameter(ParamId::Roughness)
                             : roughnessFromShininess(material.parameter(ParamId::Shininess));
}

Image openGlNormalMap(const Image& normals, bool yDown) {
  if (!yDown || normals.channels() < 2)
    return normals;
  return withGreenInverted(normals);
}

Image directXNormalMap(const Image& normals, bool yDown) {
  if (yDown || normals.channels() < 2)
    return normals;
  return withGreenInverted(normals);
}

Image engineHeightMap(const Image& height, bool heightIsDepth) {
  if (!heightIsDepth)
    return height;
  Image inverted = height;
  for (std::size_t i = 0; i < inverted.valueCount(); ++i)
    inverted.data()[i] = 1.0f - inverted.data()[i];
  return inverted;
}

bool exportsParallax(const Material& material) {
  return material.technique() != Technique::Normal && material.hasMap(MapSlot::Height);
}

std::optional<Image> packEngineMasks(const Material& material, std::string_view layoutName) {
  const PackLayout* layout = findPackLayout(layoutName);
  const Image* occlusion = material.image(MapSlot::AmbientOcclusion);
  const Image* roughness = material.image(MapSlot::Roughness);
  if (layout == nullptr || (occlusion == nullptr && roughness == nullptr))
    return std::nullopt;
  // The material's constant roughness, not the neutral 1, stands in for a missing map.
  const double constantRoughness = exportedRoughness(material);
  // Under pbr the viewport reads factor x map: bake the factor in.
  std::optional<Image> scaledRoughness;
  if (roughness && shadesPbr(material) && material.parameter(ParamId::Roughness) != 1.0) {
    scaledRoughness = *roughness;
    const float factor = float(material.parameter(ParamId::Roughness));
    for (std::size_t i = 0; i < scaledRoughness->valueCount(); ++i)
      scaledRoughness->data()[i] *= factor;
    roughness = &*scaledRoughness;
  }
  std::vector<NamedMap> maps;
  if (occlusion)
    maps.push_back({"ao", occlusion});
  if (roughness)
    maps.push_back({"roughness", roughness});
  std::vector<std::string> terms;
  for (std::string_view term : layout->terms) {
    if (term == "metallic.r")
      terms.push_back(engineNumber(exportedMetallic(material)));
    else if (roughness == nullptr && term == "roughness.r")
      terms.push_back(engineNumber(constantRoughness));
    else if (roughness == nullptr && term == "1-roughness.r")
      terms.push_back(engineNumber(1.0 - constantRoughness));
    else
      terms.emplace_back(term);
  }
  PackLayout resolved = *layout;
  resolved.terms.assign(terms.begin(), terms.end());
  Result<Image> packed = packChannels(maps, resolveLayoutTerms(resolved, maps));
  if (!packed)
    return std::nullopt;  // the maps differ in size: the slots' loader already refuses that
  return std::move(packed).value();
}

std::string stableGuid(std::string_view name) {
  // Two FNV-1a passes with different offsets: not cryptographic, only stable and spread out.
  const auto fnv = [&](std::uint64_t hash) {
    for (unsigned char c : name) {
      hash ^= c;
      hash *= 0x100000001b3ull;
    }
    return hash;
  };
  char text[33];
  std::snprintf(text, sizeof(text), "%016llx%016llx",
                static_cast<unsigned long long>(fnv(0xcbf29ce484222325ull)),
                static_cast<unsigned long long>(fnv(0x84222325cbf29ce4ull)));
  return text;
}

std::string engineNumber(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return buffer;
}

}  // namespace relief::core::inline exporters
