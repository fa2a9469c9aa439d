// Debug view names; see DebugView.h.
#include "core/view/DebugView.h"

#include <array>

namespace relief::core::inline view {
namespace {

struct ViewInfo {
  DebugView view;
  std::string_view name;
  std::string_view label;
};

constexpr std::array kViews = {
    ViewInfo{DebugView::Shading, "shading", "Shading"},
    ViewInfo{DebugView::Height, "height", "Height"},
    ViewInfo{DebugView::Normal, "normal", "Normal"},
    ViewInfo{DebugView::Uv, "uv", "Final UV"},
    ViewInfo{DebugView::Offset, "offset", "Parallax offset"},
    ViewInfo{DebugView::Steps, "steps", "Samples per pixel (cost)"},
    ViewInfo{DebugView::Shadow, "shadow", "Self-shadow"},
    ViewInfo{DebugView::Tangents, "tangents", "Tangents"},
    ViewInfo{DebugView::Mip, "mip", "Mip level"},
    ViewInfo{DebugView::Depth, "depth", "Depth"},
    ViewInfo{DebugView::Error, "error", "UV error vs exact trace"},
};

constexpr std::array kViewList = {DebugView::Shading, DebugView::Height,   DebugView::Normal,
                                  DebugView::Uv,      DebugView::Offset,   DebugView::Steps,
                                  DebugView::Shadow,  DebugView::Tangents, DebugView::Mip,
                                  DebugView::Depth,   DebugView::Error};

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
  return view == DebugView::Height || view == DebugView::Uv || view == DebugView::Offset ||
         view == DebugView::Steps || view == DebugView::Shadow || view == DebugView::Mip ||
         view == DebugView::Depth || view == DebugView::Error;
}

}  // namespace relief::core::inline view
