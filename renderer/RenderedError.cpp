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

core::Result<RenderedViews> renderErrorViews(OffscreenRenderer& offscreen,
                                             const core::Material& material,
                                             const FrameSettings& frame, int width, int height) {
  RenderedViews views;
  views.heightTexels = heightTexels(material);
  offscreen.setMaterial(material);
  for (const RenderedErrorView& view : kViews) {
    FrameSettings shaded = frame;
    shaded.view.camera.pitchDeg = view.pitchDeg;
    shaded.tiles.distance = std::max(frame.tiles.distance, 1) * view.distance;
    shaded.debugView = core::DebugView::Shading;
    shaded.output = FrameOutput::Display;
    shaded.split.reset();
    core::Result<core::Image> picture = offscreen.render(shaded, width, height);
    if (!picture)
      return core::makeError(picture.error());
    views.pictures.push_back(rgbOf(picture.value()));
    if (views.heightTexels.first > 0.0) {
      FrameSettings uv = shaded;
      uv.debugView = core::DebugView::Uv;
      uv.output = FrameOutput::FloatData;
      core::Result<core::Image> uvImage = offscreen.render(uv, width, height);
      if (!uvImage)
        return core::makeError(uvImage.error());
      views.uvs.push_back(std::move(uvImage).value());
    }
  }
  return views;
}

std::vector<RenderedErrorRow> compareRenderedViews(const RenderedViews& original,
                                                   const RenderedViews& compressed) {
  std::vector<RenderedErrorRow> rows;
  for (std::size_t v = 0; v < kViews.size(); ++v) {
    RenderedErrorRow row;
    row.view = kViews[v].name;
    const core::ImageError error =
        core::measureImageError(original.pictures[v], compressed.pictures[v]);
    row.psnr = error.psnr;
    row.mse = error.mse;
    row.flipMean = core::measureFlip(original.pictures[v], compressed.pictures[v]).mean;
    if (original.heightTexels.first > 0.0 && v < original.uvs.size() && v < compressed.uvs.size()) {
      const UvShift shift = uvShift(original.uvs[v], compressed.uvs[v], original.heightTexels);
      row.uvShiftMeanTexels = shift.mean;
      row.uvShiftP95Texels = shift.p95;
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

core::Result<std::vector<RenderedErrorRow>> measureRenderedError(OffscreenRenderer& offscreen,
                                                                 const core::Material& original,
                                                                 const core::Material& compressed,
                                                                 const FrameSettings& frame,
                                                                 int width, int height) {
  core::Result<RenderedViews> compressedViews =
      renderErrorViews(offscreen, compressed, frame, width, height);
  if (!compressedViews)
    return core::makeError(compressedViews.error());
  core::Result<RenderedViews> originalViews =
      renderErrorViews(offscreen, original, frame, width, height);
  if (!originalViews)
    return core::makeError(originalViews.error());
  RenderedViews& views = compressedViews.value();
  // The compressed material's UVs are compared in the original's height texels.
  views.heightTexels = originalViews->heightTexels;
  return compareRenderedViews(originalViews.value(), views);
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
