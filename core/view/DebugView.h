// What the viewport shows: the shaded material or one of the diagnostic views. The names are
// the CLI's --view values.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace relief::core::inline view {

enum class DebugView {
  Shading,   // the lit material
  Height,    // height at the final UV (white = top)
  Normal,    // tangent-space normal at the final UV, as n * 0.5 + 0.5
  Uv,        // final texture UV (fractional part as colour; float in EXR)
  Offset,    // parallax displacement final UV - entry UV, in texels
  Steps,     // height samples taken per pixel (view and shadow rays): the cost view
  Shadow,    // self-shadow factor (white = lit)
  Tangents,  // world-space tangent frame: tangent as colour
  Mip,       // mip level the height map is sampled at
  Depth,     // distance to the eye of what the depth buffer gets (displaced with depthOffset)
  Error,     // UV error in texels against the exact reference tracer (computed on the CPU)
};
// How many views there are (the last one + 1): DebugView.cpp's table has a row for each.
inline constexpr std::size_t kDebugViewCount = std::size_t(DebugView::Error) + 1;

std::span<const DebugView> allDebugViews();
std::string_view debugViewName(DebugView view);
std::string_view debugViewLabel(DebugView view);
std::optional<DebugView> findDebugView(std::string_view name);

// Views whose values are data, not colours: the CLI can write them as float EXR.
bool isDataView(DebugView view);

// What a view's heat map colours measure, which the viewport and `render` draw as a legend
// (renderer/HeatmapLegend.cpp); None for a view of values, not of a scale.
enum class ViewScale { None, SamplesPerPixel, MipLevel, UvErrorTexels };
ViewScale debugViewScale(DebugView view);

}  // namespace relief::core::inline view
