// ShaderVariant; see ShaderVariant.h.
#include "renderer/ShaderVariant.h"

#include "core/material/MapSlot.h"

#include <cctype>

namespace relief::renderer {
namespace {

std::vector<std::string> buildTableDefines() {
  std::vector<std::string> defines;
  for (core::DebugView view : core::allDebugViews()) {
    std::string name = "VIEW_";
    for (char c : core::debugViewName(view))  // "uv" -> VIEW_UV; a '-' in a name becomes '_'
      name += std::isalnum(static_cast<unsigned char>(c))
                  ? char(std::toupper(static_cast<unsigned char>(c)))
                  : '_';
    defines.push_back(name + " " + std::to_string(int(view)));
  }
  std::string slots = "MAP_SLOT_UNIFORMS";
  for (core::MapSlot slot : core::kAllMapSlots) {
    slots += " uniform sampler2D " + std::string(core::mapSlotSampler(slot)) + ";";
    if (!core::mapSlotPresenceFlag(slot).empty())
      slots += " uniform bool " + std::string(core::mapSlotPresenceFlag(slot)) + ";";
  }
  defines.push_back(slots);
  return defines;
}

}  // namespace

const std::vector<std::string>& materialTableDefines() {
  static const std::vector<std::string> defines = buildTableDefines();
  return defines;
}

bool hexTilingApplies(const core::Material& material, core::DebugView view, FrameOutput output) {
  return core::supportsHexTiling(material.technique()) &&
         core::UvEdge(int(material.parameter(core::ParamId::UvEdge))) == core::UvEdge::Repeat &&
         view != core::DebugView::Error && output != FrameOutput::EyeRays;
}

namespace {

std::string_view engineTraceDefine(core::EngineTrace trace) {
  switch (trace) {
    case core::EngineTrace::None:
      return {};
    case core::EngineTrace::GodotOffset:
      return "ENGINE_GODOT_OFFSET";
    case core::EngineTrace::GodotDeep:
      return "ENGINE_GODOT_DEEP";
    case core::EngineTrace::UnrealPom:
      return "ENGINE_UNREAL_POM";
    case core::EngineTrace::UrpOffset:
      return "ENGINE_URP_OFFSET";
    case core::EngineTrace::HdrpPom:
      return "ENGINE_HDRP_POM";
  }
  return {};
}

}  // namespace

// An engine preview (`engine`) compiles the engine's trace alone: no Relief technique (the
// normal technique's define reads no height), no self-shadowing (no engine material has it),
// no hex-tiling, UV clamping or curved silhouettes (Relief's options, not the engine's), and
// the depth written only where the engine writes it.
std::vector<std::string> materialShaderDefines(const core::Material& material, core::DebugView view,
                                               FrameOutput output, bool hexTiling,
                                               const core::EngineTraceParams* engine) {
  using core::ParamId;
  const bool relief = engine == nullptr;
  std::vector<std::string> defines = {std::string(
      core::techniqueShaderDefine(relief ? material.technique() : core::Technique::Normal))};
  if (!relief) {
    defines.emplace_back("ENGINE_PREVIEW");
    if (const std::string_view trace = engineTraceDefine(engine->trace); !trace.empty())
      defines.emplace_back(trace);
  }
  const auto shadowMode = core::ShadowMode(int(material.parameter(ParamId::ShadowMode)));
  if (relief && shadowMode == core::ShadowMode::Hard)
    defines.emplace_back("SHADOW_HARD");
  if (relief && shadowMode == core::ShadowMode::Soft)
    defines.emplace_back("SHADOW_SOFT");
  if (relief && core::UvEdge(int(material.parameter(ParamId::UvEdge))) == core::UvEdge::Clamp)
    defines.emplace_back("UV_EDGE_CLAMP");
  if (material.parameterFlag(ParamId::HeightInNormalAlpha))
    defines.emplace_back("HEIGHT_IN_NORMAL_ALPHA");
  if (relief && material.parameterFlag(ParamId::CurvedSilhouettes) &&
      core::isMarchingTechnique(material.technique()) && output != FrameOutput::EyeRays)
    defines.emplace_back("CURVED_SILHOUETTES");
  if (core::ShadingModel(int(material.parameter(ParamId::Shading))) == core::ShadingModel::Pbr)
    defines.emplace_back("SHADING_PBR");
  if (relief && hexTiling && hexTilingApplies(material, view, output))
    defines.emplace_back("HEX_TILING");
  if (output == FrameOutput::EyeRays) {
    defines.emplace_back("DEBUG_VIEW VIEW_RAY");  // no depth offset: nothing is shaded
    return defines;
  }
  // Displaced geometry has its depth already; an engine writes it where its material does.
  const bool writesDepth =
      relief ? material.technique() != core::Technique::Displacement : engine->depthOffset;
  if (material.parameterFlag(ParamId::DepthOffset) && writesDepth)
    defines.emplace_back("DEPTH_OFFSET");
  // The error view is computed on the CPU from a float UV pass.
  const core::DebugView shaderView = view == core::DebugView::Error ? core::DebugView::Uv : view;
  defines.push_back("DEBUG_VIEW " + std::to_string(int(shaderView)));
  if (output == FrameOutput::FloatData)
    defines.emplace_back("FLOAT_OUTPUT");
  return defines;
}

bool usesTessellation(const core::Material& material, FrameOutput output, bool enginePreview) {
  return material.technique() == core::Technique::Displacement && output != FrameOutput::EyeRays &&
         !enginePreview;
}

}  // namespace relief::renderer
