// EnginePreview; see EnginePreview.h.
#include "core/exporters/EnginePreview.h"

#include "core/exporters/EngineConversion.h"

#include <algorithm>
#include <array>

namespace relief::core::inline exporters {
namespace {

constexpr std::array kEngines = {
    EngineInfo{Engine::Godot, "godot", "Godot 4"},
    EngineInfo{Engine::Unreal, "unreal", "Unreal"},
    EngineInfo{Engine::Unity, "unity", "Unity URP"},
    EngineInfo{Engine::UnityHdrp, "unity-hdrp", "Unity HDRP"},
};

}  // namespace

std::span<const EngineInfo> allEngines() {
  return kEngines;
}

const EngineInfo& engineInfo(Engine engine) {
  return kEngines[std::size_t(engine)];
}

std::optional<Engine> findEngine(std::string_view name) {
  for (const EngineInfo& info : kEngines) {
    if (info.name == name)
      return info.engine;
  }
  return std::nullopt;
}

GodotHeightmap godotHeightmap(const Material& material) {
  GodotHeightmap heightmap;
  // Godot offsets texture coordinates by view.xy * heightmap_scale * 0.01 at full depth.
  heightmap.scale = material.parameter(ParamId::HeightScale) * 100.0;
  heightmap.deepParallax = isOccludingRelief(material.technique());
  heightmap.minLayers = int(material.parameter(ParamId::MinSamples));
  heightmap.maxLayers = int(material.parameter(ParamId::MaxSamples));
  heightmap.flipTexture = material.parameterFlag(ParamId::HeightIsDepth);
  return heightmap;
}

double unrealReferencePlane(double heightScale, double heightBias) {
  if (heightScale <= 0.0)
    return 1.0;
  return std::clamp(-heightBias / heightScale, 0.0, 1.0);
}

UnrealPom unrealPom(const Material& material) {
  const double scale = material.parameter(ParamId::HeightScale);
  const bool deep = isOccludingRelief(material.technique());
  UnrealPom pom;
  // Epic's function marches view.xy / view.z scaled by Height Ratio (the depth as a fraction of
  // the texture's width) in the UVs it is given: Relief's heightScale in tiled texture widths.
  pom.heightRatio = scale;
  pom.minSteps = deep ? material.parameter(ParamId::MinSamples) : 1.0;
  pom.maxSteps = deep ? material.parameter(ParamId::MaxSamples) : 1.0;
  pom.referencePlane = unrealReferencePlane(scale, material.parameter(ParamId::HeightBias));
  pom.pixelDepthOffset = material.parameterFlag(ParamId::DepthOffset);
  return pom;
}

double urpParallaxAmplitude(double heightScale) {
  // Head-on view.z -> 1: (h A - A/2) / 1.42 must equal Relief's h * heightScale (+ bias).
  return 1.42 * heightScale;
}

double hdrpPomAmplitudeCentimetres(double heightScale, double primitiveMetres) {
  // HDRP's uvSpaceScale = tiling * (amplitude / tiling) / primitive: the offset at full depth,
  // view.xy / view.z * amplitude / primitive, in tiled texture widths, as heightScale is.
  return 100.0 * heightScale * primitiveMetres;
}

HdrpPixelDisplacement hdrpPixelDisplacement(const Material& material) {
  const bool deep = isOccludingRelief(material.technique());
  const auto samples = [&](ParamId id) {
    return deep ? double(std::clamp(int(material.parameter(id)), 1, kHdrpMaxSamples)) : 1.0;
  };
  HdrpPixelDisplacement ppd;
  ppd.amplitudeCm =
      hdrpPomAmplitudeCentimetres(material.parameter(ParamId::HeightScale), ppd.primitiveMetres);
  ppd.minSamples = samples(ParamId::MinSamples);
  ppd.maxSamples = samples(ParamId::MaxSamples);
  ppd.depthOffset = material.parameterFlag(ParamId::DepthOffset);
  return ppd;
}

EngineTraceParams engineTrace(const Material& material, Engine engine) {
  EngineTraceParams params;
  if (!exportsParallax(material))
    return params;
  switch (engine) {
    case Engine::Godot: {
      const GodotHeightmap heightmap = godotHeightmap(material);
      params.trace = heightmap.deepParallax ? EngineTrace::GodotDeep : EngineTrace::GodotOffset;
      params.depth = heightmap.scale * 0.01;
      params.minSteps = heightmap.minLayers;
      params.maxSteps = heightmap.maxLayers;
      break;
    }
    case Engine::Unreal: {
      const UnrealPom pom = unrealPom(material);
      params.trace = EngineTrace::UnrealPom;
      params.depth = pom.heightRatio;
      params.minSteps = pom.minSteps;
      params.maxSteps = pom.maxSteps;
      params.referencePlane = pom.referencePlane;
      params.depthOffset = pom.pixelDepthOffset;
      break;
    }
    case Engine::Unity:
      params.trace = EngineTrace::UrpOffset;
      params.depth = urpParallaxAmplitude(material.parameter(ParamId::HeightScale));
      break;
    case Engine::UnityHdrp: {
      const HdrpPixelDisplacement ppd = hdrpPixelDisplacement(material);
      params.trace = EngineTrace::HdrpPom;
      // HDRP's uvSpaceScale: _InvPrimScale * tiling * amplitude in metres, the amplitude divided
      // by the tiling when the tiling scale is locked (the export's choice), so the depth in
      // tiled texture widths is the amplitude over the primitive's length.
      params.depth = ppd.amplitudeCm * 0.01 / ppd.primitiveMetres;
      params.minSteps = ppd.minSamples;
      params.maxSteps = ppd.maxSamples;
      params.lodThreshold = ppd.lodThreshold;
      params.depthOffset = ppd.depthOffset;
      break;
    }
  }
  return params;
}

std::vector<std::string> engineLosses(const Material& material, Engine engine) {
  std::vector<std::string> losses;
  const auto shadows = ShadowMode(int(material.parameter(ParamId::ShadowMode)));
  if (exportsParallax(material) && shadows != ShadowMode::Off &&
      material.parameter(ParamId::ShadowStrength) > 0.0) {
    losses.push_back(std::string(engineInfo(engine).label) +
                     "'s material does not shadow its relief: Relief's self-shadowing is lost "
                     "(the engine preview shows it without)");
  }
  return losses;
}

}  // namespace relief::core::inline exporters
