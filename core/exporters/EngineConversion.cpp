// EngineConversion; see EngineConversion.h.
#include "core/exporters/EngineConversion.h"

#include "core/generators/ChannelPacking.h"
#include "core/generators/ImageFilters.h"
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

std::vector<std::optional<Image>> resizedToLargest(const std::vector<const Image*>& maps) {
  int width = 0, height = 0;
  for (const Image* map : maps) {
    if (map && std::int64_t(map->width()) * map->height() > std::int64_t(width) * height) {
      width = map->width();
      height = map->height();
    }
  }
  std::vector<std::optional<Image>> resized(maps.size());
  for (std::size_t i = 0; i < maps.size(); ++i) {
    if (maps[i] && (maps[i]->width() != width || maps[i]->height() != height))
      resized[i] = resizeImage(*maps[i], width, height);
  }
  return resized;
}

std::optional<Image> packEngineMasks(const Material& material, std::string_view layoutName) {
  const PackLayout* layout = findPackLayout(layoutName);
  const Image* occlusion = material.image(MapSlot::AmbientOcclusion);
  const Image* roughness = material.image(MapSlot::Roughness);
  const Image* metallic = material.image(MapSlot::Metallic);
  if (layout == nullptr || (occlusion == nullptr && roughness == nullptr && metallic == nullptr))
    return std::nullopt;
  const std::vector<std::optional<Image>> resized =
      resizedToLargest({occlusion, roughness, metallic});
  if (resized[0])
    occlusion = &*resized[0];
  if (resized[1])
    roughness = &*resized[1];
  if (resized[2])
    metallic = &*resized[2];
  // The viewport reads factor x map under pbr; engines' mask maps carry no factor, so it is
  // baked in. Under classic a roughness map is the roughness itself and nothing is metal.
  const auto baked = [](const Image* map, double factor) -> std::optional<Image> {
    if (map == nullptr || factor == 1.0)
      return std::nullopt;
    Image scaled = *map;
    for (std::size_t i = 0; i < scaled.valueCount(); ++i)
      scaled.data()[i] *= float(factor);
    return scaled;
  };
  const std::optional<Image> bakedRoughness =
      baked(roughness, shadesPbr(material) ? material.parameter(ParamId::Roughness) : 1.0);
  const std::optional<Image> bakedMetallic = baked(metallic, exportedMetallic(material));
  if (bakedRoughness)
    roughness = &*bakedRoughness;
  if (bakedMetallic)
    metallic = &*bakedMetallic;
  std::vector<NamedMap> maps;
  if (occlusion)
    maps.push_back({"ao", occlusion});
  if (roughness)
    maps.push_back({"roughness", roughness});
  if (metallic)
    maps.push_back({"metallic", metallic});
  // The material's constants, not the maps' neutral values, stand in for missing maps.
  const double constantRoughness = exportedRoughness(material);
  std::vector<std::string> terms;
  for (std::string_view term : layout->terms) {
    if (metallic == nullptr && term == "metallic.r")
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
    return std::nullopt;  // not reached: the layouts' terms are valid and the sizes equal
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
