// RenderCommand; see RenderCommand.h.
#include "RenderCommand.h"

#include "app/cli/CliOptionNames.h"

#include "../DisplayCheck.h"
#include "ChooseCompression.h"
#include "CliCommon.h"
#include "RenderAnalysis.h"
#include "RenderLighting.h"

#include "core/compression/MapFile.h"
#include "core/exporters/EnginePreview.h"
#include "core/image/ImageFileTypes.h"
#include "core/image/ImageIO.h"
#include "core/mesh/MeshImport.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "core/preset/OrmTexture.h"
#include "core/tracing/UvErrorMap.h"
#include "renderer/EngineGrid.h"
#include "renderer/ErrorView.h"
#include "renderer/HeatmapLegend.h"
#include "renderer/ImageConversion.h"
#include "renderer/OffscreenRenderer.h"
#include "renderer/OpenGLProbe.h"

#include <QFileInfo>
#include <QGuiApplication>
#include <QImage>
#include <QJsonArray>
#include <QJsonObject>
#include <QPainter>
#include <QRegularExpression>
#include <QSurfaceFormat>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace relief::cli {
namespace {

QString parameterHelp() {
  QString text = QStringLiteral("\nParameters for --set (name=value):\n");
  for (const core::ParameterSpec& spec : core::allParameters()) {
    text += QStringLiteral("  ") + QString::fromStdString(core::describeOption(spec)) +
            QLatin1Char('\n');
  }
  return text;
}

// The option that gives a slot's map is the slot's name: --color, --normal, --height, --ao,
// --roughness, --metallic.
QString mapOptionName(core::MapSlot slot) {
  return qstr(core::mapSlotName(slot));
}

QString enginesList() {
  QStringList names;
  for (const core::EngineInfo& info : core::allEngines())
    names << qstr(info.name);
  return names.join(QStringLiteral(", "));
}

CliOptions renderOptions() {
  const QString file = QStringLiteral("file"), degrees = QStringLiteral("deg");
  CliOptions options = {
      {option::kOut, file, QStringLiteral("Output image (png, jpg, tga, tif, or exr)."), {}},
      {option::kSize, QStringLiteral("WxH"), QStringLiteral("Image size in pixels."),
       QStringLiteral("1280x720")},
      {option::kYaw, degrees, QStringLiteral("Camera yaw around +Y in degrees."), {}},
      {option::kPitch, degrees, QStringLiteral("Camera elevation in degrees (-89..89)."), {}},
      {option::kDistance,
       QStringLiteral("D"),
       QStringLiteral("Camera distance from the target (default: frames the mesh)."),
       {}},
      {option::kLightYaw, degrees, QStringLiteral("Light azimuth in degrees."), {}},
      {option::kLightPitch, degrees, QStringLiteral("Light elevation in degrees."), {}},
      {option::kSet,
       QStringLiteral("name=value"),
       QStringLiteral("Set a material parameter (repeatable)."),
       {}},
  };
  for (core::MapSlot slot : core::kAllMapSlots) {
    options.push_back(
        {mapOptionName(slot),
         file,
         QStringLiteral("%1 map%2.")
             .arg(qstr(core::mapSlotLabel(slot)), slot == core::MapSlot::Normal
                                                      ? QStringLiteral(" (flat when omitted)")
                                                      : QString()),
         {}});
  }
  options.push_back({option::kOrm,
                     file,
                     QStringLiteral("ORM texture: R ambient occlusion, G roughness, B metallic "
                                    "(glTF, Unreal; Poly Haven's arm). Fills those three maps; "
                                    "--ao, --roughness or --metallic given as well win."),
                     {}});
  options.push_back({option::kMesh, QStringLiteral("name|file"),
                     enumNames(core::allPrimitiveShapes(), core::primitiveShapeName) +
                         QStringLiteral(", or a mesh file (OBJ, FBX, glTF, ...)."),
                     QStringLiteral("plane")});
  options.push_back({option::kTechnique,
                     QStringLiteral("name"),
                     QStringLiteral("Overrides the preset's technique: ") +
                         enumNames(core::allTechniques(), core::techniqueName) + QLatin1Char('.'),
                     {}});
  options.push_back({option::kShading,
                     QStringLiteral("name"),
                     QStringLiteral("Overrides the preset's shading: classic (Blinn-Phong) or pbr "
                                    "(glTF metallic-roughness); as --set shading=NAME."),
                     {}});
  options.push_back({option::kView, QStringLiteral("name"),
                     QStringLiteral("What to render: ") +
                         enumNames(core::allDebugViews(), core::debugViewName) +
                         QStringLiteral(". error prints the UV error against the exact trace, "
                                        "leaving out pixels where the height map is minified "
                                        "(mip level 1 or more; grey in the picture)."),
                     QStringLiteral("shading")});
  options.push_back({option::kRepeats, QStringLiteral("n"),
                     QStringLiteral("Tile preview: repeat the material N times more in each "
                                    "direction than its tiling says (the GUI's Tile 3x3)."),
                     QStringLiteral("1")});
  options.push_back(
      {option::kFarther, QStringLiteral("n"),
       QStringLiteral("Look as from N times farther (the GUI's Distance xN): the material repeats "
                      "N times more, so the mip levels an engine samples there are drawn, from "
                      "the chains the preset's compression choices write (mipmaps, mip filter)."),
       QStringLiteral("1")});
  options.push_back({option::kSeams,
                     {},
                     QStringLiteral("Tile preview: draw lines where the maps' edges meet."),
                     {}});
  options.push_back({option::kHex,
                     {},
                     QStringLiteral("Hex-tiling against visible repetition (the GUI's Hex): "
                                    "not with cone, quadtree or displacement."),
                     {}});
  options.push_back(
      {option::kCostTable,
       {},
       QStringLiteral("Instead of an image: each technique (normal, parallax, POM at 8-32, "
                      "16-64 and 32-128 samples, relief, cone, quadtree, displacement) with its "
                      "frame time (fastest and median of timed frames) and its UV error against "
                      "the exact trace at this view and size, the cheapest within --max-error "
                      "marked. With --json, as one object."),
       {}});
  options.push_back(
      {option::kCompressionError,
       {},
       QStringLiteral("Instead of an image: compress every map the preset has a compression "
                      "choice for, render the material with the original and the compressed "
                      "maps close, grazing and 8 times farther, and print the differences (PSNR, "
                      "FLIP, parallax UV shift in texels). relief-cli compare --rendered PRESET "
                      "is the same."),
       {}});
  options.push_back(
      {option::kSlot,
       QStringLiteral("slot"),
       QStringLiteral("With --compression-error: instead of the preset's choices, measure each "
                      "DDS or KTX2 file given after the preset in this map slot (color, normal, "
                      "height, ...) alone, with the mip chain the file holds: one row a file, "
                      "the mean FLIP and PSNR of the three views."),
       {}});
  options.push_back({option::kMaxError, QStringLiteral("texels"),
                     QStringLiteral("The cost table's error bound: the mean UV error the "
                                    "cheapest technique must stay within."),
                     QStringLiteral("0.25")});
  options.push_back({option::kEngine,
                     QStringLiteral("name|grid"),
                     QStringLiteral("Trace the relief as that engine's exported material does: ") +
                         enginesList() +
                         QStringLiteral(" (docs/techniques.md, \"Engine previews\"). grid: "
                                        "Relief's exact trace and every engine side by side, "
                                        "each with its UV error against the exact trace "
                                        "(printed too; --size is one panel's)."),
                     {}});
  for (CliOption& option : lightingOptions())
    options.push_back(std::move(option));
  options.push_back(strictOption(QStringLiteral("rendering")));
  options.push_back(jsonOption());
  options.push_back(
      {option::kStats,
       {},
       QStringLiteral("Also measure the frame's cost and print it as one JSON object: "
                      "{\"frame_ms\": the median frame time, each frame drawn and finished "
                      "(glFinish), over at least 10 frames and 1 second; \"frame_ms_min\": "
                      "the fastest frame, the steadiest figure to rank techniques by on a "
                      "busy machine; \"frame_ms_p90\"; \"frames\"; \"frame_spread\": "
                      "(p90 - fastest) / median; \"samples_per_pixel\": {\"mean\", "
                      "\"p95\", \"max\"} height samples (texel fetches) per covered pixel, "
                      "\"pixels\": covered pixels}. With --json, in its object."),
       {}});
  options.push_back(
      {option::kFormat,
       QStringLiteral("png|exr"),
       QStringLiteral("png (8-bit colours, legends on heat maps) or exr (float: raw values of "
                      "data views such as uv, offset, steps, depth, error; the shading view's "
                      "linear radiance, unclamped). Default: from --out."),
       {}});
  for (CliOption& choose : chooseCompressionOptions())
    options.push_back(std::move(choose));
  return options;
}

struct RenderRequest {
  bool engineGrid = false;                     // --engine grid
  bool costTable = false;                      // --cost-table
  bool compressionError = false;               // --compression-error (compare --rendered)
  std::optional<core::MapSlot> candidateSlot;  // --slot: compare these files in that slot
  QStringList candidateFiles;
  bool progressLines = false;           // --progress-lines
  std::optional<ChooseRequest> choose;  // --choose-compression (compress --preset)
  double maxError = 0.25;               // --max-error
  core::Material material;
  core::Mesh mesh;
  renderer::FrameSettings frame;
  int width = 1280;
  int height = 720;
  QString outPath;
  bool exr = false;
  bool json = false;
  bool stats = false;
  core::ViewState presetView;  // the preset's camera, light and mesh, used unless overridden
  std::array<core::MapCompression, core::kMapSlotCount> compression;  // the preset's choices
  QString presetPath;  // as given, for messages about files the preset names
};

bool loadMapOption(const QCommandLineParser& parser, const QString& option, core::MapSlot slot,
                   core::Material& material) {
  if (!parser.isSet(option))
    return true;
  const QString path = parser.value(option);
  core::Result<core::Image> image = core::loadMapFile(path.toStdString());
  if (!image) {
    printError(QString::fromStdString(image.error()));
    return false;
  }
  material.setMap(slot, std::make_shared<core::Image>(std::move(image).value()),
                  QFileInfo(path).absoluteFilePath().toStdString());
  return true;
}

// Paints the heat-map legend of the view (if it has one) onto an 8-bit picture.
void addLegend(core::Image& image, const RenderRequest& request) {
  const auto legend =
      renderer::legendFor(request.frame.debugView, request.material, core::kErrorDisplayTexels);
  if (!legend)
    return;
  QImage picture = renderer::toDisplayImage(image);
  {
    QPainter painter(&picture);
    renderer::drawHeatmapLegend(painter, picture.rect(), *legend);
  }
  image = renderer::fromQImage(picture, image.colorSpace());
}

// The requested view: 8-bit display colours with a legend, or for EXR the raw values of data
// views and the shading view's linear radiance (linear colour for the other views).
core::Result<core::Image> renderView(renderer::OffscreenRenderer& offscreen,
                                     const RenderRequest& request) {
  renderer::FrameSettings frame = request.frame;
  const bool raw = request.exr && (core::isDataView(frame.debugView) ||
                                   frame.debugView == core::DebugView::Shading);
  frame.output = raw ? renderer::FrameOutput::FloatData : renderer::FrameOutput::Display;
  core::Result<core::Image> image = offscreen.render(frame, request.width, request.height);
  if (!image || raw)
    return image;
  if (request.exr) {
    for (std::size_t i = 0; i < image->valueCount(); ++i) {
      if (i % 4 != 3)
        image->data()[i] = core::srgbToLinear(image->data()[i]);
    }
    image->setColorSpace(core::ColorSpace::Linear);
    return image;
  }
  addLegend(image.value(), request);
  return image;
}

// The error view: the exact tracer against this frame's UVs. Prints the statistics; writes the
// heat map (PNG, with legend) or the error in texels (EXR, 1 channel, -1 where empty).
core::Result<core::Image> renderErrorView(renderer::OffscreenRenderer& offscreen,
                                          const RenderRequest& request, QJsonObject& report) {
  auto inputs = offscreen.renderErrorViewInputs(request.frame, request.width, request.height);
  if (!inputs)
    return core::makeError(inputs.error());
  const core::UvErrorMap map =
      core::computeUvErrorMap(inputs->finalUv, inputs->eyeRays, inputs->field);
  report.insert(QStringLiteral("uvErrorTexels"),
                QJsonObject{{QStringLiteral("mean"), map.mean},
                            {QStringLiteral("p95"), map.p95},
                            {QStringLiteral("max"), map.maximum},
                            {QStringLiteral("pixels"), double(map.pixels)},
                            {QStringLiteral("minifiedPixels"), double(map.minifiedPixels)}});
  if (!request.json) {
    printOut(QStringLiteral("UV error against the exact trace: %1\n")
                 .arg(QString::fromStdString(core::describeUvError(map))));
  }
  if (request.exr)
    return map.texels;
  core::Image colors = core::colorizeErrorMap(map, core::kErrorDisplayTexels);
  // Uncovered pixels get the background of a normal render, so the picture reads as a frame.
  core::Result<core::Image> background =
      offscreen.render(request.frame.view, request.width, request.height);
  if (background) {
    for (std::size_t p = 0; p < colors.pixelCount(); ++p) {
      if (colors.data()[p * 4 + 3] == 0.0f) {
        for (int c = 0; c < 4; ++c)
          colors.data()[p * 4 + c] = background->data()[p * 4 + c];
      }
    }
  }
  addLegend(colors, request);
  return colors;
}

// --out and --format: the file and whether it holds 8-bit colours or float values.
std::optional<int> parseOutput(const QCommandLineParser& parser, RenderRequest& request) {
  request.outPath = parser.value(option::kOut);
  const QString outSuffix = QFileInfo(request.outPath).suffix().toLower();
  const QString format =
      parser.isSet(option::kFormat)
          ? parser.value(option::kFormat).toLower()
          : (outSuffix == QStringLiteral("exr") ? QStringLiteral("exr") : QStringLiteral("png"));
  if (format != QStringLiteral("png") && format != QStringLiteral("exr")) {
    printError(QStringLiteral("--format %1: expected png or exr").arg(format));
    return kExitUsage;
  }
  request.exr = format == QStringLiteral("exr");
  const core::ImageFileType* type = core::imageFileTypeForPath(request.outPath.toStdString());
  if (request.exr && outSuffix != QStringLiteral("exr")) {
    printError(QStringLiteral("--out %1: --format exr writes an .exr file").arg(request.outPath));
    return kExitUsage;
  }
  if (!request.exr && (!type || type->isFloat)) {
    printError(QStringLiteral("--out %1: the image type must be one of png, jpg, tga, tif (or "
                              "exr with --format exr)")
                   .arg(request.outPath));
    return kExitUsage;
  }
  return std::nullopt;
}

// The preset (if given) and the map options, which replace the preset's maps.
std::optional<int> loadMaterial(const QCommandLineParser& parser, RenderRequest& request) {
  const QStringList positional = parser.positionalArguments();
  if (!positional.isEmpty()) {
    core::Result<core::LoadedPreset> loaded = core::loadPreset(positional.front().toStdString());
    if (!loaded) {
      printError(QString::fromStdString(loaded.error()));
      return kExitFailure;
    }
    if (!acceptPresetProblems(loaded->warnings, parser.isSet(option::kStrict)))
      return kExitFailure;
    request.material = std::move(loaded->preset.material);
    request.presetView = loaded->preset.view;
    request.compression = loaded->preset.compression;
    // Each map sampled through the mip chain its compression choice ships (the viewport's rule).
    for (core::MapSlot slot : core::kAllMapSlots) {
      request.frame.mipChains[std::size_t(slot)] =
          core::shippedMipChain(loaded->preset.compression[std::size_t(slot)]);
    }
    request.presetPath = positional.front();
  }
  if (parser.isSet(option::kOrm)) {
    const QString path = parser.value(option::kOrm);
    core::Result<std::vector<core::ChannelMap>> maps = core::loadOrmTexture(path.toStdString());
    if (!maps) {
      printError(QString::fromStdString(maps.error()));
      return kExitFailure;
    }
    for (core::ChannelMap& map : maps.value()) {
      request.material.setMap(map.slot, std::make_shared<core::Image>(std::move(map.image)),
                              QFileInfo(path).absoluteFilePath().toStdString(), map.channel);
    }
  }
  // A missing normal map is flat.
  for (core::MapSlot slot : core::kAllMapSlots) {
    if (!loadMapOption(parser, mapOptionName(slot), slot, request.material))
      return kExitFailure;
  }
  return std::nullopt;
}

// --set, --technique, --shading and --view.
std::optional<int> applyOverrides(const QCommandLineParser& parser, RenderRequest& request) {
  for (const QString& assignment : parser.values(option::kSet)) {
    const qsizetype equals = assignment.indexOf(QLatin1Char('='));
    if (equals <= 0) {
      printError(QStringLiteral("--set %1: expected name=value").arg(assignment));
      return kExitUsage;
    }
    const std::string name = assignment.left(equals).trimmed().toStdString();
    const std::optional<core::ParamId> id = core::findParameter(name);
    if (!id) {
      printError(QStringLiteral("--set: unknown parameter '%1' (see --help for the list)")
                     .arg(QString::fromStdString(name)));
      return kExitUsage;
    }
    core::Result<double> value = core::parseOptionValue(
        core::parameterSpec(*id), assignment.mid(equals + 1).trimmed().toStdString());
    if (!value) {
      printError(QStringLiteral("--set: ") + QString::fromStdString(value.error()));
      return kExitUsage;
    }
    request.material.setParameter(*id, value.value());
  }
  if (parser.isSet(option::kTechnique)) {
    const QString name = parser.value(option::kTechnique);
    const std::optional<core::Technique> technique = core::findTechnique(name.toStdString());
    if (!technique) {
      printError(QStringLiteral("--technique %1: expected one of %2")
                     .arg(name, enumNames(core::allTechniques(), core::techniqueName)));
      return kExitUsage;
    }
    request.material.setTechnique(*technique);
  }
  if (parser.isSet(option::kShading)) {
    core::Result<double> shading = core::parseOptionValue(
        core::parameterSpec(core::ParamId::Shading), parser.value(option::kShading).toStdString());
    if (!shading) {
      printError(QStringLiteral("--shading: ") + QString::fromStdString(shading.error()));
      return kExitUsage;
    }
    request.material.setParameter(core::ParamId::Shading, shading.value());
  }
  const QString viewName = parser.value(option::kView);
  const std::optional<core::DebugView> view = core::findDebugView(viewName.toStdString());
  if (!view) {
    printError(QStringLiteral("--view %1: expected one of %2")
                   .arg(viewName, enumNames(core::allDebugViews(), core::debugViewName)));
    return kExitUsage;
  }
  request.frame.debugView = *view;
  const std::optional<int> repeats = integerOption(parser, option::kRepeats, 1, 1, 64);
  if (!repeats)
    return kExitUsage;
  const std::optional<int> farther = integerOption(parser, option::kFarther, 1, 1, 64);
  if (!farther)
    return kExitUsage;
  request.frame.tiles = {*repeats, parser.isSet(option::kSeams), parser.isSet(option::kHex),
                         *farther};
  if (parser.isSet(option::kEngine)) {
    const QString engine = parser.value(option::kEngine);
    request.engineGrid = engine == QStringLiteral("grid");
    request.frame.engine = core::findEngine(engine.toStdString());
    if (!request.engineGrid && !request.frame.engine) {
      printError(
          QStringLiteral("--engine %1: expected grid or one of %2").arg(engine, enginesList()));
      return kExitUsage;
    }
  }
  return std::nullopt;
}

// --mesh, --size and the camera and light options (over the preset's view).
std::optional<int> resolveView(const QCommandLineParser& parser, RenderRequest& request) {
  const bool meshFromPreset = !parser.isSet(option::kMesh) && !request.presetView.mesh.empty();
  const QString meshName = meshFromPreset ? QString::fromStdString(request.presetView.mesh)
                                          : parser.value(option::kMesh);
  const QString meshNamedBy =
      meshFromPreset ? request.presetPath + QStringLiteral(": view.mesh") : QString();
  if (auto exit = resolveMesh(meshName, request.mesh, meshNamedBy))
    return *exit;
  static const QRegularExpression sizePattern(QStringLiteral("^(\\d{1,5})x(\\d{1,5})$"));
  const QRegularExpressionMatch size = sizePattern.match(parser.value(option::kSize));
  if (!size.hasMatch() || size.captured(1).toInt() < 1 || size.captured(2).toInt() < 1) {
    printError(QStringLiteral("--size %1: expected WIDTHxHEIGHT, e.g. 1280x720")
                   .arg(parser.value(option::kSize)));
    return kExitUsage;
  }
  request.width = size.captured(1).toInt();
  request.height = size.captured(2).toInt();
  core::OrbitCamera& camera = request.frame.view.camera;
  core::DirectionalLight& light = request.frame.view.light;
  if (request.presetView.camera)
    camera = *request.presetView.camera;
  if (auto exit =
          applyLightingOptions(parser, request.presetView, request.presetPath, request.frame.view))
    return exit;
  const auto yaw = numberOption(parser, option::kYaw, camera.yawDeg);
  const auto pitch = numberOption(parser, option::kPitch, camera.pitchDeg);
  const auto distance = numberOption(parser, option::kDistance, 0.0);
  const auto lightYaw = numberOption(parser, option::kLightYaw, light.azimuthDeg);
  const auto lightPitch = numberOption(parser, option::kLightPitch, light.elevationDeg);
  if (!yaw || !pitch || !distance || !lightYaw || !lightPitch)
    return kExitUsage;
  if (*pitch < core::OrbitCamera::kMinPitchDeg || *pitch > core::OrbitCamera::kMaxPitchDeg ||
      (parser.isSet(option::kDistance) && *distance <= 0.0) || *lightPitch < -90.0 ||
      *lightPitch > 90.0) {
    printError(
        QStringLiteral("--pitch must be within -89..89 degrees, --light-pitch within "
                       "-90..90 and --distance positive"));
    return kExitUsage;
  }
  camera.yawDeg = float(*yaw);
  camera.pitchDeg = float(*pitch);
  // Framed from these angles as the viewport frames a mesh (key F), unless --distance is given
  // or the preset holds the camera exactly as it was saved.
  const bool savedView =
      request.presetView.camera && !parser.isSet(option::kYaw) && !parser.isSet(option::kPitch);
  if (!savedView)
    camera.frame(request.mesh.bounds(), float(request.width) / float(request.height));
  if (*distance > 0.0)
    camera.distance = float(*distance);
  light.azimuthDeg = float(*lightYaw);
  light.elevationDeg = float(*lightPitch);
  return std::nullopt;
}

// The frame's cost (--stats): frame times and the height samples per covered pixel.
core::Result<QJsonObject> measureCost(renderer::OffscreenRenderer& offscreen,
                                      const RenderRequest& request) {
  renderer::FrameSettings shaded = request.frame;
  shaded.debugView = core::DebugView::Shading;
  shaded.output = renderer::FrameOutput::Display;
  core::Result<renderer::FrameTimes> times =
      offscreen.timeFrames(shaded, request.width, request.height, renderer::FrameTiming{});
  if (!times)
    return core::makeError(times.error());
  core::Result<renderer::SampleCount> samples =
      offscreen.countHeightSamples(request.frame, request.width, request.height);
  if (!samples)
    return core::makeError(samples.error());
  return QJsonObject{
      {QStringLiteral("frame_ms"), times->median},
      {QStringLiteral("frame_ms_min"), times->fastest},
      {QStringLiteral("frame_ms_p90"), times->p90},
      {QStringLiteral("frames"), times->frames},
      {QStringLiteral("frame_spread"), times->spread()},
      {QStringLiteral("samples_per_pixel"), QJsonObject{{QStringLiteral("mean"), samples->mean},
                                                        {QStringLiteral("p95"), samples->p95},
                                                        {QStringLiteral("max"), samples->max}}},
      {QStringLiteral("pixels"), double(samples->pixels)}};
}

// Fills `request` from the command line; returns an exit code on failure.
std::optional<int> buildRequest(const QCommandLineParser& parser, RenderRequest& request) {
  const QStringList positional = parser.positionalArguments();
  request.json = parser.isSet(option::kJson);
  request.stats = parser.isSet(option::kStats);
  request.costTable = parser.isSet(option::kCostTable);
  request.compressionError = parser.isSet(option::kCompressionError);
  request.progressLines = parser.isSet(option::kProgressLines);
  if (parser.isSet(option::kSlot)) {
    const QString name = parser.value(option::kSlot);
    request.candidateSlot = core::findMapSlot(name.toStdString());
    if (!request.candidateSlot) {
      printError(QStringLiteral("--slot: unknown map slot '%1'").arg(name));
      return kExitUsage;
    }
    if (!request.compressionError || positional.size() < 2) {
      printError(QStringLiteral("--slot compares files in one slot: compare --rendered PRESET "
                                "--slot %1 FILE.ktx2 [FILE.dds ...]")
                     .arg(name));
      return kExitUsage;
    }
    request.candidateFiles = positional.mid(1);
  } else if (positional.size() > 1) {
    printError(QStringLiteral("render takes at most one preset (see --help)"));
    return kExitUsage;
  }
  if (parser.isSet(option::kChooseCompression)) {
    if (positional.isEmpty()) {
      printError(
          QStringLiteral("compress --preset PRESET: give the preset whose maps to choose "
                         "formats for"));
      return kExitUsage;
    }
    request.choose.emplace();
    if (auto exit = parseChooseRequest(parser, positional.front(), *request.choose))
      return exit;
    request.compressionError = true;  // a table, no image: the same checks below
  }
  if (request.compressionError && positional.isEmpty()) {
    printError(
        QStringLiteral("--compression-error measures a preset's compression choices: "
                       "give the preset"));
    return kExitUsage;
  }
  const std::optional<double> maxError =
      numberOption(parser, option::kMaxError, core::kErrorDisplayTexels);
  if (!maxError || *maxError < 0.0) {
    if (maxError)
      printError(QStringLiteral("--max-error: expected texels, 0 or more"));
    return kExitUsage;
  }
  request.maxError = *maxError;
  if (parser.isSet(option::kOut) && (request.costTable || request.compressionError)) {
    printError(request.choose
                   ? QStringLiteral("compress --preset writes into --out-dir: drop --out")
                   : QStringLiteral("%1 prints a table and writes no image: drop --out")
                         .arg(request.costTable ? QStringLiteral("--cost-table")
                                                : QStringLiteral("--compression-error")));
    return kExitUsage;
  }
  if (!parser.isSet(option::kOut) && !request.costTable && !request.compressionError) {
    printError(QStringLiteral("render needs --out FILE (see --help)"));
    return kExitUsage;
  }
  if (parser.isSet(option::kOut)) {
    if (auto exit = parseOutput(parser, request))
      return exit;
  }
  bool anyMap = parser.isSet(option::kOrm);
  for (core::MapSlot slot : core::kAllMapSlots)
    anyMap = anyMap || parser.isSet(mapOptionName(slot));
  if (positional.isEmpty() && !anyMap) {
    printError(QStringLiteral("render needs a preset or maps (--color, --normal, --height, ...)"));
    return kExitUsage;
  }
  if (auto exit = loadMaterial(parser, request))
    return exit;
  if (auto exit = applyOverrides(parser, request))
    return exit;
  if (auto exit = resolveView(parser, request))
    return exit;
  // The chooser renders every candidate from three views: a smaller frame unless one is asked.
  if (request.choose) {
    const renderer::ChooserRequest defaults;
    if (!parser.isSet(option::kSize)) {
      request.width = defaults.width;
      request.height = defaults.height;
    }
    request.choose->chooser.width = request.width;
    request.choose->chooser.height = request.height;
  }
  return std::nullopt;
}

}  // namespace

namespace {

// Parses a render command line into `request`; an exit code when parsing decided the outcome.
// `compare --rendered` is `render --compression-error` under the compare command's name.
std::optional<int> parseRender(QStringList arguments, RenderRequest& request) {
  if (arguments.size() > 1 && arguments[1] == QStringLiteral("compare"))
    arguments.replaceInStrings(QRegularExpression(QStringLiteral("^--rendered$")),
                               QStringLiteral("--compression-error"));
  if (arguments.size() > 1 && arguments[1] == QStringLiteral("compress"))
    arguments = chooseCompressionArguments(std::move(arguments));
  QCommandLineParser parser;
  parser.setApplicationDescription(
      QStringLiteral("Render a material offscreen, exactly as the editor's viewport shows it. "
                     "Needs an X display: use xvfb-run on headless machines.") +
      parameterHelp());
  parser.addPositionalArgument(QStringLiteral("preset"),
                               QStringLiteral("A .relief preset (optional when maps are given)."),
                               QStringLiteral("[preset.relief]"));
  addOptions(parser, renderOptions());
  if (auto exit = parseOrExit(parser, arguments,
                              QStringLiteral("relief-cli render [preset.relief] --out FILE "
                                             "[options]"))) {
    return *exit;
  }
  if (auto exit = buildRequest(parser, request))
    return *exit;
  return std::nullopt;
}

// Renders `request` with `offscreen`, writes the image and prints what was asked.
int renderRequest(renderer::OffscreenRenderer& offscreen, const RenderRequest& request) {
  offscreen.setMesh(request.mesh);
  offscreen.setMaterial(request.material);
  QJsonObject report;
  if (request.choose) {
    ChooseRequest choose = *request.choose;
    choose.chooser.presetChoices = request.compression;
    return runChooseCompression(offscreen, request.material, request.frame, choose, request.json);
  }
  if (request.candidateSlot) {
    return printCandidateErrors(offscreen, request.material, *request.candidateSlot,
                                request.candidateFiles, request.frame, request.width,
                                request.height, request.json, request.progressLines);
  }
  if (request.compressionError) {
    return printCompressionError(offscreen, request.material, request.compression, request.frame,
                                 request.width, request.height, request.json);
  }
  if (request.costTable) {
    return printCostTable(offscreen, request.frame, request.width, request.height, request.maxError,
                          request.json);
  }
  core::Result<core::Image> image = request.engineGrid
                                        ? renderEngineGrid(offscreen, request.frame, request.width,
                                                           request.height, request.json, report)
                                    : request.frame.debugView == core::DebugView::Error
                                        ? renderErrorView(offscreen, request, report)
                                        : renderView(offscreen, request);
  if (!image) {
    printError(QStringLiteral("render: ") + QString::fromStdString(image.error()));
    return kExitFailure;
  }
  const core::SampleFormat sampleFormat =
      request.exr ? core::SampleFormat::Float : core::SampleFormat::UInt8;
  if (core::Status saved =
          core::saveImage(image.value(), request.outPath.toStdString(), sampleFormat);
      !saved) {
    printError(QString::fromStdString(saved.error()));
    return kExitFailure;
  }
  if (request.stats) {
    core::Result<QJsonObject> cost = measureCost(offscreen, request);
    if (!cost) {
      printError(QStringLiteral("render --stats: ") + QString::fromStdString(cost.error()));
      return kExitFailure;
    }
    if (!request.json) {
      printJson(cost.value());
      return kExitOk;
    }
    for (auto it = cost->begin(); it != cost->end(); ++it)
      report.insert(it.key(), it.value());
  }
  if (request.json) {
    report.insert(QStringLiteral("output"), request.outPath);
    report.insert(QStringLiteral("width"), request.width);
    report.insert(QStringLiteral("height"), request.height);
    report.insert(QStringLiteral("view"), qstr(core::debugViewName(request.frame.debugView)));
    report.insert(QStringLiteral("technique"),
                  qstr(core::techniqueName(request.material.technique())));
    if (request.frame.engine)
      report.insert(QStringLiteral("engine"), qstr(core::engineInfo(*request.frame.engine).name));
    printJson(report);
  }
  return kExitOk;
}

RenderSession* g_session = nullptr;

}  // namespace

int runRender(int argc, char* argv[]) {
  RenderRequest request;
  if (auto exit = parseRender(argumentsFrom(argc, argv), request))
    return *exit;
  if (const std::string problem = app::displayProblem(); !problem.empty()) {
    printError(QStringLiteral("render: ") + QString::fromStdString(problem));
    return kExitFailure;
  }
  QSurfaceFormat::setDefaultFormat(renderer::requiredSurfaceFormat());
  QGuiApplication application(argc, argv);
  auto offscreen = renderer::OffscreenRenderer::create();
  if (!offscreen) {
    printError(QStringLiteral("render: ") + QString::fromStdString(offscreen.error()));
    return kExitFailure;
  }
  return renderRequest(*offscreen.value(), request);
}

RenderSession::RenderSession() {
  g_session = this;
}

RenderSession::~RenderSession() {
  g_session = nullptr;
}

int RenderSession::runJob(const QStringList& arguments) {
  RenderRequest request;
  if (auto exit = parseRender(arguments, request))
    return *exit;
  if (!g_session) {
    printError(QStringLiteral("render: no render session (a program error)"));
    return kExitFailure;
  }
  if (!g_session->m_offscreen) {
    auto offscreen = renderer::OffscreenRenderer::create();
    if (!offscreen) {
      printError(QStringLiteral("render: ") + QString::fromStdString(offscreen.error()));
      return kExitFailure;
    }
    g_session->m_offscreen = std::move(offscreen.value());
  }
  return renderRequest(*g_session->m_offscreen, request);
}

}  // namespace relief::cli
