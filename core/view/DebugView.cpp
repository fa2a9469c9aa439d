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
  return view == DebugView::Height || view == DebugView::Uv || view == DebugView::Offset ||
         view == DebugView::Steps || view == DebugView::Shadow || view == DebugView::Mip ||
         view == DebugView::Depth || view == DebugView::Error;
}

}  // namespace relief::core::inline view
