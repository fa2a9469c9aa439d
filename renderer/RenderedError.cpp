// RenderedError; see RenderedError.h.
#include "renderer/RenderedError.h"

#include "core/compression/CompressionMetrics.h"
#include "core/compression/Flip.h"
#include "renderer/OffscreenRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace relief::renderer {
namespace {

constexpr std::array kViews = {
    RenderedErrorView{"close", 35.0f, 1},
    RenderedErrorView{"grazing", 12.0f, 1},
    RenderedErrorView{"far", 35.0f, 8},
};

// The texels per unit of UV of the height the shaders read (the normal map's when the height is
// packed in its alpha); 0 without relief.
std::pair<double, double> heightTexels(const core::Material& material) {
  const core::MapSlot slot = material.parameterFlag(core::ParamId::HeightInNormalAlpha)
                                 ? core::MapSlot::Normal
                                 : core::MapSlot::Height;
  const core::Image* height = material.image(slot);
  return height ? std::pair{double(height->width()), double(height->height())}
                : std::pair{0.0, 0.0};
}

struct UvShift {
  double mean = 0.0;
  double p95 = 0.0;
};

// Over pixels both UV views cover (alpha > 0).
UvShift uvShift(const core::Image& a, const core::Image& b, std::pair<double, double> texels) {
  std::vector<double> shifts;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      if (a.at(x, y, 3) <= 0.0f || b.at(x, y, 3) <= 0.0f)
        continue;
      const double du = (double(a.at(x, y, 0)) - b.at(x, y, 0)) * texels.first;
      const double dv = (double(a.at(x, y, 1)) - b.at(x, y, 1)) * texels.second;
      shifts.push_back(std::sqrt(du * du + dv * dv));
    }
  }
  if (shifts.empty())
    return {};
  double sum = 0.0;
  for (double s : shifts)
    sum += s;
  const auto p95 = shifts.begin() + std::ptrdiff_t(0.95 * double(shifts.size() - 1));
  std::nth_element(shifts.begin(), p95, shifts.end());
  return {sum / double(shifts.size()), *p95};
}

core::Image rgbOf(const core::Image& image) {
  core::Image rgb(image.width(), image.height(), 3, image.colorSpace());
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      for (int c = 0; c < 3; ++c)
        rgb.at(x, y, c) = image.at(x, y, c);
    }
  }
  return rgb;
}

}  // namespace

std::span<const RenderedErrorView> renderedErrorViews() {
  return kViews;
}

core::Result<std::vector<RenderedErrorRow>> measureRenderedError(OffscreenRenderer& offscreen,
                                                                 const core::Material& original,
                                                                 const core::Material& compressed,
                                                                 const FrameSettings& frame,
                                                                 int width, int height) {
  const std::pair<double, double> texels = heightTexels(original);
  std::vector<RenderedErrorRow> rows;
  for (const RenderedErrorView& view : kViews) {
    FrameSettings shaded = frame;
    shaded.view.camera.pitchDeg = view.pitchDeg;
    shaded.tiles.distance = std::max(frame.tiles.distance, 1) * view.distance;
    shaded.debugView = core::DebugView::Shading;
    shaded.output = FrameOutput::Display;
    shaded.split.reset();
    FrameSettings uv = shaded;
    uv.debugView = core::DebugView::Uv;
    uv.output = FrameOutput::FloatData;
    core::Image pictures[2], uvs[2];
    const core::Material* materials[2] = {&original, &compressed};
    for (int i = 0; i < 2; ++i) {
      offscreen.setMaterial(*materials[i]);
      core::Result<core::Image> picture = offscreen.render(shaded, width, height);
      if (!picture)
        return core::makeError(picture.error());
      pictures[i] = rgbOf(picture.value());
      if (texels.first > 0.0) {
        core::Result<core::Image> uvImage = offscreen.render(uv, width, height);
        if (!uvImage)
          return core::makeError(uvImage.error());
        uvs[i] = std::move(uvImage).value();
      }
    }
    RenderedErrorRow row;
    row.view = view.name;
    row.psnr = core::measureImageError(pictures[0], pictures[1]).psnr;
    row.flipMean = core::measureFlip(pictures[0], pictures[1]).mean;
    if (texels.first > 0.0) {
      const UvShift shift = uvShift(uvs[0], uvs[1], texels);
      row.uvShiftMeanTexels = shift.mean;
      row.uvShiftP95Texels = shift.p95;
    }
    rows.push_back(std::move(row));
  }
  offscreen.setMaterial(original);
  return rows;
}

std::string describeRenderedError(const std::vector<RenderedErrorRow>& rows) {
  std::string text;
  char line[200];
  for (const RenderedErrorRow& row : rows) {
    char psnr[32] = "identical";
    if (!std::isinf(row.psnr))
      std::snprintf(psnr, sizeof psnr, "%.2f dB", row.psnr);
    std::snprintf(
        line, sizeof line, "%-8s PSNR %-10s FLIP %.4f  UV shift %.3f texels mean, %.3f p95\n",
        row.view.c_str(), psnr, row.flipMean, row.uvShiftMeanTexels, row.uvShiftP95Texels);
    text += line;
  }
  return text;
}

}  // namespace relief::renderer
