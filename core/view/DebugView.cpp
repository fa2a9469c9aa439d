// Debug view names; see DebugView.h.
#include "core/view/DebugView.h"

#include <array>

namespace relief::core::inline view {
namespace {

struct ViewInfo {
  DebugView view;
  std::string_view name;  // also the shaders' VIEW_<NAME> (renderer/ShaderVariant.cpp)
  std::string_view label;
  bool data;  // values, not colours: written as float EXR on request
  ViewScale scale;
};

using enum ViewScale;
constexpr std::array kViews = {
    ViewInfo{DebugView::Shading, "shading", "Shading", false, None},
    ViewInfo{DebugView::Height, "height", "Height", true, None},
    ViewInfo{DebugView::Normal, "normal", "Normal", false, None},
    ViewInfo{DebugView::Uv, "uv", "Final UV", true, None},
    ViewInfo{DebugView::Offset, "offset", "Parallax offset", true, None},
    ViewInfo{DebugView::Steps, "steps", "Samples per pixel (cost)", true, SamplesPerPixel},
    ViewInfo{DebugView::Shadow, "shadow", "Self-shadow", true, None},
    ViewInfo{DebugView::Tangents, "tangents", "Tangents", false, None},
    ViewInfo{DebugView::Mip, "mip", "Mip level", true, MipLevel},
    ViewInfo{DebugView::Depth, "depth", "Depth", true, None},
    ViewInfo{DebugView::Error, "error", "UV error vs exact trace", true, UvErrorTexels},
};

static_assert(kViews.size() == kDebugViewCount, "one row per debug view");
constexpr bool rowsInEnumOrder() {
  for (std::size_t i = 0; i < kViews.size(); ++i) {
    if (std::size_t(kViews[i].view) != i)
      return false;
  }
  return true;
}
static_assert(rowsInEnumOrder(), "debugViewName and debugViewLabel index the rows by view");

constexpr std::array<DebugView, kViews.size()> viewList() {
  std::array<DebugView, kViews.size()> list{};
  for (std::size_t i = 0; i < kViews.size(); ++i)
    list[i] = kViews[i].view;
  return list;
}
constexpr std::array kViewList = viewList();

}  // namespace

std::span<const DebugView> allDebugViews() {
  return kViewList;
}
std::string_view debugViewName(DebugView view) {
  return kViews[std::size_t(view)].name;
}
std::string_view debugViewLabel(DebugView view) {
  return kViews[std::size_t(view)].label;
}

std::optional<DebugView> findDebugView(std::string_view name) {
  for (const ViewInfo& info : kViews) {
    if (info.name == name)
      return info.view;
  }
  return std::nullopt;
}

bool isDataView(DebugView view) {
  return kViews[std::size_t(view)].data;
}
ViewScale debugViewScale(DebugView view) {
  return kViews[std::size_t(view)].scale;
}

}  // namespace relief::core::inline view
