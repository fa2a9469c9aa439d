// RenderCommand; see RenderCommand.h.
#include "RenderCommand.h"

#include "../DisplayCheck.h"
#include "CliCommon.h"
#include "core/ImageIO.h"
#include "core/MaterialPreset.h"
#include "core/MeshPrimitives.h"
#include "renderer/OffscreenRenderer.h"
#include "renderer/OpenGLProbe.h"

#include <QFileInfo>
#include <QGuiApplication>
#include <QRegularExpression>
#include <QSurfaceFormat>

namespace relief::cli {
namespace {

QString parameterHelp() {
  QString text = QStringLiteral("\nParameters for --set (name=value):\n");
  for (const core::ParameterSpec& spec : core::allParameters()) {
    text += QStringLiteral("  ") + QString::fromStdString(core::describeParameter(spec)) +
            QLatin1Char('\n');
  }
  return text;
}

struct RenderRequest {
  core::Material material;
  core::Mesh mesh;
  renderer::RenderView view;
  int width = 1280;
  int height = 720;
  QString outPath;
};

bool loadMapOption(const QCommandLineParser& parser, const QString& option, core::MapSlot slot,
                   core::Material& material) {
  if (!parser.isSet(option))
    return true;
  const QString path = parser.value(option);
  core::Result<core::Image> image = core::loadImage(path.toStdString());
  if (!image) {
    printError(QString::fromStdString(image.error()));
    return false;
  }
  material.setMap(slot, std::make_shared<core::Image>(std::move(image).value()),
                  QFileInfo(path).absoluteFilePath().toStdString());
  return true;
}

// Fills `request` from the command line; returns an exit code on failure.
std::optional<int> buildRequest(const QCommandLineParser& parser, RenderRequest& request) {
  const QStringList positional = parser.positionalArguments();
  if (positional.size() > 1) {
    printError(QStringLiteral("render takes at most one preset (see --help)"));
    return kExitUsage;
  }
  if (!parser.isSet(QStringLiteral("out"))) {
    printError(QStringLiteral("render needs --out FILE (see --help)"));
    return kExitUsage;
  }
  request.outPath = parser.value(QStringLiteral("out"));
  const QString outSuffix = QFileInfo(request.outPath).suffix().toLower();
  static const QStringList kOutSuffixes = {QStringLiteral("png"),  QStringLiteral("jpg"),
                                           QStringLiteral("jpeg"), QStringLiteral("tga"),
                                           QStringLiteral("tif"),  QStringLiteral("tiff")};
  if (!kOutSuffixes.contains(outSuffix)) {
    printError(QStringLiteral("--out %1: the image type must be one of png, jpg, tga, tif")
                   .arg(request.outPath));
    return kExitUsage;
  }
  const bool anyMap = parser.isSet(QStringLiteral("color")) ||
                      parser.isSet(QStringLiteral("normal")) ||
                      parser.isSet(QStringLiteral("height"));
  if (positional.isEmpty() && !anyMap) {
    printError(QStringLiteral("render needs a preset or maps (--color, --normal, --height)"));
    return kExitUsage;
  }

  if (!positional.isEmpty()) {
    core::Result<core::LoadedPreset> loaded = core::loadPreset(positional.front().toStdString());
    if (!loaded) {
      printError(QString::fromStdString(loaded.error()));
      return kExitFailure;
    }
    for (const std::string& warning : loaded->warnings) {
      printError(QStringLiteral("warning: ") + QString::fromStdString(warning));
    }
    request.material = std::move(loaded->material);
  }
  // Maps given on the command line replace the preset's (a missing normal map is flat).
  if (!loadMapOption(parser, QStringLiteral("color"), core::MapSlot::Color, request.material) ||
      !loadMapOption(parser, QStringLiteral("normal"), core::MapSlot::Normal, request.material) ||
      !loadMapOption(parser, QStringLiteral("height"), core::MapSlot::Height, request.material) ||
      !loadMapOption(parser, QStringLiteral("ao"), core::MapSlot::AmbientOcclusion,
                     request.material) ||
      !loadMapOption(parser, QStringLiteral("roughness"), core::MapSlot::Roughness,
                     request.material)) {
    return kExitFailure;
  }

  for (const QString& assignment : parser.values(QStringLiteral("set"))) {
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
    core::Result<double> value = core::parseParameterValue(
        core::parameterSpec(*id), assignment.mid(equals + 1).trimmed().toStdString());
    if (!value) {
      printError(QStringLiteral("--set: ") + QString::fromStdString(value.error()));
      return kExitUsage;
    }
    request.material.setParameter(*id, value.value());
  }

  const QString meshName = parser.value(QStringLiteral("mesh"));
  const std::optional<core::PrimitiveShape> shape =
      core::findPrimitiveShape(meshName.toStdString());
  if (!shape) {
    printError(QStringLiteral("--mesh %1: expected plane, cube or sphere").arg(meshName));
    return kExitUsage;
  }
  request.mesh = core::makePrimitive(*shape);

  static const QRegularExpression sizePattern(QStringLiteral("^(\\d{1,5})x(\\d{1,5})$"));
  const QRegularExpressionMatch size = sizePattern.match(parser.value(QStringLiteral("size")));
  if (!size.hasMatch() || size.captured(1).toInt() < 1 || size.captured(2).toInt() < 1) {
    printError(QStringLiteral("--size %1: expected WIDTHxHEIGHT, e.g. 1280x720")
                   .arg(parser.value(QStringLiteral("size"))));
    return kExitUsage;
  }
  request.width = size.captured(1).toInt();
  request.height = size.captured(2).toInt();
  core::OrbitCamera& camera = request.view.camera;
  core::DirectionalLight& light = request.view.light;
  const auto yaw = numberOption(parser, QStringLiteral("yaw"), camera.yawDeg);
  const auto pitch = numberOption(parser, QStringLiteral("pitch"), camera.pitchDeg);
  const auto distance = numberOption(parser, QStringLiteral("distance"), 0.0);
  const auto lightYaw = numberOption(parser, QStringLiteral("light-yaw"), light.azimuthDeg);
  const auto lightPitch = numberOption(parser, QStringLiteral("light-pitch"), light.elevationDeg);
  if (!yaw || !pitch || !distance || !lightYaw || !lightPitch)
    return kExitUsage;
  if (*pitch < core::OrbitCamera::kMinPitchDeg || *pitch > core::OrbitCamera::kMaxPitchDeg ||
      (parser.isSet(QStringLiteral("distance")) && *distance <= 0.0) || *lightPitch < -90.0 ||
      *lightPitch > 90.0) {
    printError(
        QStringLiteral("--pitch must be within -89..89 degrees, --light-pitch within "
                       "-90..90 and --distance positive"));
    return kExitUsage;
  }
  camera.yawDeg = float(*yaw);
  camera.pitchDeg = float(*pitch);
  // Framed from these angles as the viewport frames a mesh (key F), unless --distance is given.
  camera.frame(request.mesh.bounds(), float(request.width) / float(request.height));
  if (*distance > 0.0)
    camera.distance = float(*distance);
  light.azimuthDeg = float(*lightYaw);
  light.elevationDeg = float(*lightPitch);
  return std::nullopt;
}

}  // namespace

int runRender(int argc, char* argv[]) {
  const QStringList arguments = argumentsFrom(argc, argv);
  QCommandLineParser parser;
  parser.setApplicationDescription(
      QStringLiteral("Render a material offscreen, exactly as the editor's viewport shows it. "
                     "Needs an X display: use xvfb-run on headless machines.") +
      parameterHelp());
  parser.addPositionalArgument(QStringLiteral("preset"),
                               QStringLiteral("A .relief preset (optional when maps are given)."),
                               QStringLiteral("[preset.relief]"));
  const auto option = [&parser](const QString& name, const QString& description,
                                const QString& valueName = {}, const QString& fallback = {}) {
    parser.addOption(QCommandLineOption(name, description, valueName, fallback));
  };
  option(QStringLiteral("out"), QStringLiteral("Output image (png, jpg, tga, tif)."),
         QStringLiteral("file"));
  option(QStringLiteral("size"), QStringLiteral("Image size in pixels (default 1280x720)."),
         QStringLiteral("WxH"), QStringLiteral("1280x720"));
  option(QStringLiteral("yaw"), QStringLiteral("Camera yaw around +Y in degrees."),
         QStringLiteral("deg"));
  option(QStringLiteral("pitch"), QStringLiteral("Camera elevation in degrees (-89..89)."),
         QStringLiteral("deg"));
  option(QStringLiteral("distance"),
         QStringLiteral("Camera distance from the target (default: frames the mesh)."),
         QStringLiteral("D"));
  option(QStringLiteral("light-yaw"), QStringLiteral("Light azimuth in degrees."),
         QStringLiteral("deg"));
  option(QStringLiteral("light-pitch"), QStringLiteral("Light elevation in degrees."),
         QStringLiteral("deg"));
  option(QStringLiteral("set"), QStringLiteral("Set a material parameter (repeatable)."),
         QStringLiteral("name=value"));
  option(QStringLiteral("color"), QStringLiteral("Colour map (sRGB)."), QStringLiteral("file"));
  option(QStringLiteral("normal"), QStringLiteral("Normal map (flat when omitted)."),
         QStringLiteral("file"));
  option(QStringLiteral("height"), QStringLiteral("Height map."), QStringLiteral("file"));
  option(QStringLiteral("ao"), QStringLiteral("Ambient occlusion map."), QStringLiteral("file"));
  option(QStringLiteral("roughness"), QStringLiteral("Roughness map."), QStringLiteral("file"));
  option(QStringLiteral("mesh"), QStringLiteral("plane, cube or sphere (default plane)."),
         QStringLiteral("name"), QStringLiteral("plane"));
  if (auto exit = parseOrExit(parser, arguments,
                              QStringLiteral("relief-cli render [preset.relief] --out FILE "
                                             "[options]"))) {
    return *exit;
  }

  RenderRequest request;
  if (auto exit = buildRequest(parser, request))
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
  offscreen.value()->setMesh(request.mesh);
  offscreen.value()->setMaterial(request.material);
  core::Result<core::Image> image =
      offscreen.value()->render(request.view, request.width, request.height);
  if (!image) {
    printError(QStringLiteral("render: ") + QString::fromStdString(image.error()));
    return kExitFailure;
  }
  if (core::Status saved =
          core::saveImage(image.value(), request.outPath.toStdString(), core::SampleFormat::UInt8);
      !saved) {
    printError(QString::fromStdString(saved.error()));
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace relief::cli
