// bench-mips: what folding the normals' spread into the roughness mips
// (core/compression/RoughnessFold.h) buys where it matters, far away. For each sample material,
// made shiny (a roughness map of 0.25 at the normal map's size, factor 1, metallic 0, the studio
// environment and a grazing key light, no self-shadowing), the viewport's frame is rendered seen
// from 8 times farther (levels 2 to 4 of the maps are sampled) three ways:
//   reference: 8 times the resolution (level 0 to 1 sampled), box-filtered down in linear light;
//   plain:     the renormalised normal chain, the roughness chain averaged;
//   folded:    the same normals, the roughness chain widened by their spread (Toksvig).
// and the mean error of plain and folded against the reference is printed (sRGB steps of 255,
// over the pixels the plane covers), with the reduction. All in one run, so ratios compare.
//
// Run: xvfb-run -a build/release/tools/bench-mips [distance, default 8]
#include "core/image/ColorSpace.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "renderer/OffscreenRenderer.h"
#include "renderer/OpenGLProbe.h"

#include <QGuiApplication>
#include <QSurfaceFormat>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#ifndef RELIEF_SOURCE_DIR
#error "RELIEF_SOURCE_DIR must point at the source tree (for the samples)"
#endif

namespace relief {
namespace {

constexpr int kWidth = 320, kHeight = 240, kSuper = 8;

// `image` box-filtered by `factor` in linear light, re-encoded to sRGB (the Display output).
core::Image downsampleLinear(const core::Image& image, int factor) {
  core::Image out(image.width() / factor, image.height() / factor, image.channels());
  for (int y = 0; y < out.height(); ++y) {
    for (int x = 0; x < out.width(); ++x) {
      for (int c = 0; c < image.channels(); ++c) {
        double sum = 0.0;
        for (int j = 0; j < factor; ++j) {
          for (int i = 0; i < factor; ++i) {
            const float v = image.at(x * factor + i, y * factor + j, c);
            sum += c < 3 ? core::srgbToLinear(v) : v;
          }
        }
        const float mean = float(sum / (factor * factor));
        out.at(x, y, c) = c < 3 ? core::linearToSrgb(mean) : mean;
      }
    }
  }
  return out;
}

// Mean absolute RGB difference in 8-bit steps over the pixels `mask` covers (alpha > 0).
double meanError(const core::Image& a, const core::Image& b, const core::Image& mask) {
  double sum = 0.0;
  long count = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      if (mask.at(x, y, 3) <= 0.0f)
        continue;
      for (int c = 0; c < 3; ++c)
        sum += std::abs(double(a.at(x, y, c)) - b.at(x, y, c)) * 255.0;
      count += 3;
    }
  }
  return count ? sum / double(count) : 0.0;
}

}  // namespace
}  // namespace relief

int main(int argc, char* argv[]) {
  using namespace relief;
  QSurfaceFormat::setDefaultFormat(renderer::requiredSurfaceFormat());
  QGuiApplication application(argc, argv);
  const int distance = argc > 1 ? std::max(1, std::atoi(argv[1])) : 8;
  auto created = renderer::OffscreenRenderer::create();
  if (!created) {
    std::fprintf(stderr, "bench-mips: %s\n", created.error().c_str());
    return 1;
  }
  renderer::OffscreenRenderer& offscreen = *created.value();
  const core::Mesh plane = core::makePlane();
  offscreen.setMesh(plane);
  std::printf(
      "bench-mips: %dx%d seen from %dx farther, reference %dx supersampled; mean error "
      "in sRGB steps over the plane\n\n",
      kWidth, kHeight, distance, kSuper);
  std::printf("%-13s %10s %10s %10s\n", "sample", "plain", "folded", "reduction");
  for (const char* sample : {"bricks", "cobblestones", "tiles"}) {
    auto preset = core::loadPreset(std::string(RELIEF_SOURCE_DIR) + "/samples/" + sample + "/" +
                                   sample + ".relief");
    if (!preset) {
      std::fprintf(stderr, "bench-mips: %s\n", preset.error().c_str());
      return 1;
    }
    core::Material material = preset->preset.material;
    const core::Image& normals = *material.image(core::MapSlot::Normal);
    auto roughness = std::make_shared<core::Image>(normals.width(), normals.height(), 1);
    for (std::size_t i = 0; i < roughness->valueCount(); ++i)
      roughness->data()[i] = 0.25f;
    material.setMap(core::MapSlot::Roughness, roughness);
    material.setParameter(core::ParamId::Roughness, 1.0);
    material.setParameter(core::ParamId::Metallic, 0.0);
    material.setParameter(core::ParamId::ShadowMode, double(core::ShadowMode::Off));
    offscreen.setMaterial(material);

    renderer::FrameSettings frame;
    frame.view.camera.yawDeg = 0.0f;
    frame.view.camera.pitchDeg = 40.0f;
    frame.view.camera.frame(plane.bounds(), float(kWidth) / kHeight);
    frame.view.light.azimuthDeg = 180.0f;  // against the view: a broad glancing highlight
    frame.view.light.elevationDeg = 30.0f;
    frame.tiles.distance = distance;
    const auto render = [&](bool fold, int scale) {
      frame.mipChains[std::size_t(core::MapSlot::Roughness)] = {true, core::MipFilter::Box, fold};
      core::Result<core::Image> image = offscreen.render(frame, kWidth * scale, kHeight * scale);
      if (!image) {
        std::fprintf(stderr, "bench-mips: %s\n", image.error().c_str());
        std::exit(1);
      }
      return std::move(image).value();
    };
    const core::Image reference = downsampleLinear(render(false, kSuper), kSuper);
    const core::Image plain = render(false, 1);
    const core::Image folded = render(true, 1);
    const double plainError = meanError(plain, reference, plain);
    const double foldedError = meanError(folded, reference, plain);
    std::printf("%-13s %10.3f %10.3f %9.1f%%\n", sample, plainError, foldedError,
                100.0 * (1.0 - foldedError / plainError));
  }
  return 0;
}
