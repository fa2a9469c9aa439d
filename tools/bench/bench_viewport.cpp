// bench-viewport: what each parallax technique costs. Renders 1280x720 offscreen for every
// technique x sample count x view (head-on, 45 degrees, grazing 15 degrees) with the
// cobblestones sample on a plane that fills the frame in every view, times draw + glFinish on the
// CPU clock (GL timer queries report nonsense on llvmpipe), takes the median of
// several runs and prints each row's ratio to `normal` for the same view, measured in the same run.
//
// A second table times the shading models (classic Blinn-Phong, pbr metallic-roughness with the
// studio environment's image-based light) on the same techniques and views, and the bench prints
// how long prefiltering an environment takes (once per environment change, never per frame).
//
// The quadtree's and cone's rows include nothing of building their pyramid and cone map (once
// per height map, not per frame); the bench prints those builds' times for a 4096x4096 map after
// the tables, and what uploading a 4096x4096 map with its mip chain takes.
//
// Run: xvfb-run -a build/release/tools/bench-viewport [repeats, default 5] [--shading-only |
// --uploads-only]
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "core/shading/EnvironmentMaps.h"
#include "core/tracing/ConeMap.h"
#include "core/tracing/MaxMipPyramid.h"
#include "renderer/MaterialRenderer.h"
#include "renderer/OpenGLProbe.h"
#include "renderer/TextureCache.h"
#include "tools/bench/MedianTime.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSurfaceFormat>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#ifndef RELIEF_SOURCE_DIR
#error "RELIEF_SOURCE_DIR must point at the source tree (for the samples)"
#endif

namespace {

using namespace relief;

struct ViewSetup {
  const char* name;
  float pitchDeg;
};

struct Row {
  std::string technique;
  std::string samples;
  std::string shadows;
  double milliseconds[3];
};

// Each shading cell alternates classic and pbr this many times (see benchShading).
constexpr int kShadingRounds = 5;
struct ShadingRow {
  std::string label;
  double classic[3];
  double pbr[3];
  double ratio[3];
};

// The quadtree's pyramid and the cone technique's cone map for a 4096x4096 height map, built
// in core from the cobblestones height tiled 4 x 4 (real data at that size). Median of 3
// (cones) and 5 (pyramid).
bool benchTracerBuilds(const core::Material& base) {
  const core::Image& cobbles = *base.map(core::MapSlot::Height).image;
  core::Image tiled(4096, 4096, 1);
  for (int y = 0; y < tiled.height(); ++y) {
    for (int x = 0; x < tiled.width(); ++x)
      tiled.at(x, y, 0) = cobbles.at(x % cobbles.width(), y % cobbles.height(), 0);
  }
  core::MaxMipPyramid pyramid;
  const double pyramidMs =
      bench::medianMilliseconds(5, [&] { pyramid = core::buildMaxMipPyramid(tiled, 0, false); });
  if (pyramid.levels.size() != 13)
    return 1;
  core::ConeMap cones;
  const double conesMs =
      bench::medianMilliseconds(3, [&] { cones = core::buildConeMap(tiled, 0, false); });
  std::vector<float> ratios = cones.ratios;
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  std::printf(
      "\n4096x4096 height map (cobblestones tiled 4x4): quadtree pyramid %.1f ms (median of "
      "5), cone map %.0f ms (median of 3; median cone ratio %.1f texels per unit height)\n",
      pyramidMs, conesMs, double(ratios[ratios.size() / 2]));

  return true;
}

// Uploading a 4096x4096 map: level 0 alone, and with core's box and Kaiser chains (what the
// viewport samples: the chain the map ships with, renderer/TextureCache.h), once per map and
// chain change, never per frame. Each is draw-independent: upload + glFinish.
void benchMapUploads(const core::Material& base) {
  std::printf("\n4096x4096 map uploads (median of 3; upload + glFinish):\n");
  QOpenGLFunctions* gl = QOpenGLContext::currentContext()->functions();
  for (core::MapSlot slot : {core::MapSlot::Color, core::MapSlot::Normal, core::MapSlot::Height}) {
    const core::Image& source = *base.map(slot).image;
    core::Image tiled(4096, 4096, source.channels(), source.colorSpace());
    for (int y = 0; y < tiled.height(); ++y) {
      for (int x = 0; x < tiled.width(); ++x) {
        for (int c = 0; c < source.channels(); ++c)
          tiled.at(x, y, c) = source.at(x % source.width(), y % source.height(), c);
      }
    }
    const auto upload = [&](core::MipChainSpec chain) {
      return bench::medianMilliseconds(3, [&] {
        auto texture = renderer::createMapTexture(tiled, slot, chain);
        gl->glFinish();
      });
    };
    const double alone = upload({false, core::MipFilter::Box});
    const double box = upload({true, core::MipFilter::Box});
    const double kaiser = upload({true, core::MipFilter::Kaiser});
    std::printf("  %-7s level 0 alone %6.0f ms, box chain %6.0f ms, Kaiser chain %6.0f ms\n",
                std::string(core::mapSlotName(slot)).c_str(), alone, box, kaiser);
  }
}

// Prefiltering each built-in, and a 4096 x 2048 environment (the working width files are
// resized to; the studio made at that size): upload, mips, the GGX chain and the irradiance.
void benchEnvironmentPrefilter(renderer::MaterialRenderer& materialRenderer) {
  std::printf("\nenvironment prefiltering (upload, mips, GGX chain, irradiance; median of 3):");
  std::vector<std::pair<std::string, std::shared_ptr<const core::Image>>> sources;
  for (core::BuiltInEnvironment builtIn : core::allBuiltInEnvironments()) {
    const std::string name(core::builtInEnvironmentName(builtIn));
    sources.emplace_back(name, core::environmentRadiance(name).value());
  }
  sources.emplace_back("4096x2048",
                       std::make_shared<const core::Image>(
                           core::makeBuiltInEnvironment(core::BuiltInEnvironment::Studio, 2048)));
  for (const auto& [name, radiance] : sources) {
    renderer::EnvironmentLight& light = materialRenderer.environmentLight();
    std::vector<double> times;
    for (int i = 0; i < 3; ++i) {
      light.prepare(std::make_shared<const core::Image>(*radiance));  // a new image: prefilters
      times.push_back(light.lastPrefilterMilliseconds());
    }
    std::sort(times.begin(), times.end());
    std::printf(" %s (%dx%d) %.0f ms;", name.c_str(), radiance->width(), radiance->height(),
                times[1]);
  }
  std::printf("\n");
}

// The technique table (each view's time and its ratio to normal mapping's) and the shading
// table (pbr against classic), as Markdown.
void printTables(const std::vector<Row>& rows, const std::vector<ShadingRow>& shadingRows) {
  std::printf(
      "| technique        | samples | shadows  | head-on ms (x normal) | 45 deg ms (x normal) "
      "| grazing ms (x normal) | head-on / grazing |\n");
  std::printf(
      "|------------------|---------|----------|-----------------------|---------------------"
      "-|-----------------------|-------------------|\n");
  for (const Row& row : rows) {
    std::printf("| %-16s | %-7s | %-8s |", row.technique.c_str(), row.samples.c_str(),
                row.shadows.c_str());
    for (int v = 0; v < 3; ++v) {
      std::printf(" %8.1f (%5.2fx)      |", row.milliseconds[v],
                  row.milliseconds[v] / rows.front().milliseconds[v]);
    }
    std::printf(" %17.2f |\n", row.milliseconds[0] / row.milliseconds[2]);
  }
  std::printf(
      "\n| shading: pbr (studio light) / classic, median of %d alternating rounds | head-on ms "
      "| 45 deg ms | grazing ms |\n"
      "|---|---|---|---|\n",
      kShadingRounds);
  for (const ShadingRow& row : shadingRows) {
    std::printf("| %s |", row.label.c_str());
    for (int v = 0; v < 3; ++v)
      std::printf(" %.1f / %.1f (%.2fx) |", row.pbr[v], row.classic[v], row.ratio[v]);
    std::printf("\n");
  }
}

// The three views every row is timed from.
constexpr ViewSetup kViews[3] = {{"head-on", 89.0f}, {"45 deg", 45.0f}, {"grazing", 15.0f}};

// Draws `material` from a view and returns the median frame time in milliseconds.
using FrameTimer = std::function<double(const core::Material&, const ViewSetup&)>;

// The technique table's rows: normal mapping, every other technique at its sample counts, and
// POM with soft shadows (`shadowed`).
std::vector<Row> benchTechniques(const core::Material& base, const core::Material& normal,
                                 const core::Material& shadowed, const FrameTimer& timeFrame) {
  std::vector<Row> rows;
  const auto measure = [&](const core::Material& material, std::string samples,
                           std::string shadows) {
    Row row{std::string(core::techniqueName(material.technique())),
            std::move(samples),
            std::move(shadows),
            {}};
    for (int v = 0; v < 3; ++v)
      row.milliseconds[v] = timeFrame(material, kViews[v]);
    rows.push_back(row);
    std::fprintf(stderr, ".");
  };
  measure(normal, "-", "off");
  for (core::Technique technique : core::allTechniques()) {
    if (technique == core::Technique::Normal)
      continue;
    // Parallax takes two samples whatever the count, the quadtree and cone walk as far as the ray
    // needs and displacement tessellates (at its default cap): one row each. POM also runs at
    // 64/256, the count issue 13 races the quadtree with.
    const bool marching = core::isMarchingTechnique(technique) && !core::isExactTracing(technique);
    for (int most : {8, 16, 32, 64, 256}) {
      if (!marching && most != 8)
        continue;
      if (most == 256 && technique != core::Technique::Pom)
        continue;
      core::Material material = base;
      material.setTechnique(technique);
      material.setParameter(core::ParamId::MinSamples, most / 4);
      material.setParameter(core::ParamId::MaxSamples, most);
      std::string setting = marching ? std::to_string(most / 4) + "/" + std::to_string(most) : "-";
      if (technique == core::Technique::Displacement)
        setting = "tess " + std::to_string(int(material.parameter(core::ParamId::MaxTessellation)));
      measure(material, setting, "off");
    }
  }
  measure(shadowed, "8/32", "soft, 16");
  return rows;
}

// Shading models: the same technique and view under classic and pbr (issue 12: pbr at most
// 1.3x classic). This machine's speed drifts by tens of percent within a minute, so each cell
// alternates the two `kShadingRounds` times and reports the median of the rounds' ratios (and
// the median times), rather than the ratio of two medians taken seconds apart.
std::vector<ShadingRow> benchShading(const core::Material& base, const core::Material& normal,
                                     const core::Material& shadowed, const FrameTimer& timeFrame) {
  const auto median = [](std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
  };
  std::vector<ShadingRow> shadingRows;
  core::Material pomPlain = base;
  pomPlain.setTechnique(core::Technique::Pom);
  core::Material quadtree = base;
  quadtree.setTechnique(core::Technique::Quadtree);
  for (const auto& [label, material] : {std::pair<std::string, core::Material>{"normal", normal},
                                        {"pom 8/32", pomPlain},
                                        {"pom 8/32, soft shadows", shadowed},
                                        {"quadtree", quadtree}}) {
    ShadingRow row{label, {}, {}, {}};
    core::Material pbr = material;
    pbr.setParameter(core::ParamId::Shading, double(int(core::ShadingModel::Pbr)));
    for (int v = 0; v < 3; ++v) {
      std::vector<double> classicTimes, pbrTimes, ratios;
      for (int round = 0; round < kShadingRounds; ++round) {
        classicTimes.push_back(timeFrame(material, kViews[v]));
        pbrTimes.push_back(timeFrame(pbr, kViews[v]));
        ratios.push_back(pbrTimes.back() / classicTimes.back());
      }
      row.classic[v] = median(classicTimes);
      row.pbr[v] = median(pbrTimes);
      row.ratio[v] = median(ratios);
    }
    shadingRows.push_back(row);
    std::fprintf(stderr, ".");
  }
  return shadingRows;
}

}  // namespace

int main(int argc, char* argv[]) {
  QSurfaceFormat::setDefaultFormat(renderer::requiredSurfaceFormat());
  QGuiApplication application(argc, argv);
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const bool shadingOnly = argc > 2 && std::string(argv[2]) == "--shading-only";
  const bool uploadsOnly = argc > 2 && std::string(argv[2]) == "--uploads-only";
  const int width = 1280, height = 720;

  if (auto probe = renderer::probeOpenGL(); !probe) {
    std::fprintf(stderr, "bench-viewport: %s\n", probe.error().c_str());
    return 1;
  }
  QOpenGLContext context;
  context.setFormat(renderer::requiredSurfaceFormat());
  QOffscreenSurface surface;
  surface.setFormat(renderer::requiredSurfaceFormat());
  surface.create();
  if (!context.create() || !context.makeCurrent(&surface)) {
    std::fprintf(stderr, "bench-viewport: cannot create an OpenGL 4.1 context\n");
    return 1;
  }
  auto preset = core::loadPreset(std::string(RELIEF_SOURCE_DIR) +
                                 "/samples/cobblestones/cobblestones.relief");
  if (!preset) {
    std::fprintf(stderr, "bench-viewport: %s\n", preset.error().c_str());
    return 1;
  }
  // A plane ten times the default, tiled ten times as often: the same texel density, and it
  // fills the frame even at grazing angles, so every view shades the same number of pixels.
  // Its grid is the editor plane's too (what displacement tessellates).
  const core::Mesh plane = core::makePlane(20.0f, 10 * core::kPrimitiveFaceSegments);
  core::Material base = preset->preset.material;
  base.setParameter(core::ParamId::Tiling, base.parameter(core::ParamId::Tiling) * 10.0);
  base.setParameter(core::ParamId::ShadowMode, double(core::ShadowMode::Off));
  // The technique table and the shading table's reference are classic (the sample shades pbr).
  base.setParameter(core::ParamId::Shading, double(int(core::ShadingModel::Classic)));

  renderer::MaterialRenderer materialRenderer;
  if (auto status = materialRenderer.initialize(); !status) {
    std::fprintf(stderr, "bench-viewport: %s\n", status.error().c_str());
    return 1;
  }
  materialRenderer.setMesh(plane);
  if (uploadsOnly) {
    benchMapUploads(base);
    return 0;
  }

  const FrameTimer timeFrame = [&](const core::Material& material, const ViewSetup& setup) {
    materialRenderer.setMaterial(material);
    renderer::FrameSettings frame;
    frame.view.camera.yawDeg = 0.0f;
    frame.view.camera.pitchDeg = setup.pitchDeg;
    frame.view.camera.distance = 1.6f;
    // A narrow field of view keeps each view pure: at "grazing" every pixel sees the surface
    // between 5 and 25 degrees, instead of a spread from the horizon to 35 degrees.
    frame.view.camera.fovYDeg = 20.0f;
    // An untimed first frame, then the median of `repeats` frames.
    core::Result<renderer::FrameTimes> times = materialRenderer.timeFrames(
        frame, width, height, renderer::FrameTiming{repeats, 0.0, repeats});
    return times ? times->median : -1.0;
  };

  core::Material normal = base;
  normal.setTechnique(core::Technique::Normal);
  core::Material shadowed = base;
  shadowed.setTechnique(core::Technique::Pom);
  shadowed.setParameter(core::ParamId::ShadowMode, double(core::ShadowMode::Soft));
  const std::vector<Row> rows =
      shadingOnly ? std::vector<Row>{} : benchTechniques(base, normal, shadowed, timeFrame);
  const std::vector<ShadingRow> shadingRows = benchShading(base, normal, shadowed, timeFrame);
  std::fprintf(stderr, "\n");

  std::printf(
      "bench-viewport: %dx%d, cobblestones (1024^2 maps), median of %d frames, "
      "draw + glFinish\n%s\n\n",
      width, height, repeats, materialRenderer.rendererDescription().c_str());
  printTables(rows, shadingRows);
  if (shadingOnly)
    return 0;
  if (!benchTracerBuilds(base))
    return 1;
  benchMapUploads(base);
  benchEnvironmentPrefilter(materialRenderer);
  materialRenderer.releaseResources();
  context.doneCurrent();
  return 0;
}
