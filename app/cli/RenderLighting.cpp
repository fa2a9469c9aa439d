// RenderLighting; see RenderLighting.h.
#include "RenderLighting.h"

#include "app/cli/CliOptionNames.h"

#include "core/shading/EnvironmentMaps.h"

namespace relief::cli {
namespace {

// Light intensities a preset may hold (core/preset/MaterialPreset.cpp reads the same range).
constexpr double kMaxLightIntensity = 100.0;

std::optional<int> applyDisplay(const QCommandLineParser& parser, core::DisplayTransform& display) {
  const auto exposure = numberOption(parser, option::kExposure, display.exposureEv);
  if (!exposure)
    return kExitUsage;
  if (*exposure < core::DisplayTransform::kMinExposureEv ||
      *exposure > core::DisplayTransform::kMaxExposureEv) {
    printError(QStringLiteral("--exposure must be within %1..%2 stops")
                   .arg(core::DisplayTransform::kMinExposureEv)
                   .arg(core::DisplayTransform::kMaxExposureEv));
    return kExitUsage;
  }
  display.exposureEv = float(*exposure);
  if (parser.isSet(option::kTonemap)) {
    const QString name = parser.value(option::kTonemap);
    const std::optional<core::ToneMapper> mapper = core::findToneMapper(name.toStdString());
    if (!mapper) {
      printError(QStringLiteral("--tonemap %1: expected one of %2")
                     .arg(name, enumNames(core::allToneMappers(), core::toneMapperName)));
      return kExitUsage;
    }
    display.toneMapper = *mapper;
  }
  return std::nullopt;
}

std::optional<int> applyEnvironment(const QCommandLineParser& parser, const QString& presetPath,
                                    core::Environment& environment) {
  QString namedBy;  // where the source came from, when not from --environment
  if (parser.isSet(option::kEnvironment))
    environment.source = parser.value(option::kEnvironment).toStdString();
  else if (!presetPath.isEmpty())
    namedBy = presetPath + QStringLiteral(": view.environment.source");
  const auto intensity = numberOption(parser, option::kEnvironmentIntensity, environment.intensity);
  const auto rotation = numberOption(parser, option::kEnvironmentRotation, environment.rotationDeg);
  if (!intensity || !rotation)
    return kExitUsage;
  if (*intensity < 0.0 || *intensity > core::Environment::kMaxIntensity) {
    printError(QStringLiteral("--environment-intensity must be within 0..%1")
                   .arg(core::Environment::kMaxIntensity));
    return kExitUsage;
  }
  environment.intensity = float(*intensity);
  environment.rotationDeg = float(std::remainder(*rotation, 360.0));
  if (parser.isSet(option::kBackground)) {
    const QString name = parser.value(option::kBackground);
    const std::optional<core::Background> background = core::findBackground(name.toStdString());
    if (!background) {
      printError(QStringLiteral("--background %1: expected one of %2")
                     .arg(name, enumNames(core::allBackgrounds(), core::backgroundName)));
      return kExitUsage;
    }
    environment.background = *background;
  }
  // Read now: a missing or bad file is the command's error, not a silent uniform fallback.
  if (const auto radiance = core::environmentRadiance(environment.source); !radiance) {
    printError(prefixedBy(namedBy, radiance.error()));
    return kExitFailure;
  }
  return std::nullopt;
}

}  // namespace

CliOptions lightingOptions() {
  return {
      {option::kLightIntensity,
       QStringLiteral("X"),
       QStringLiteral("Multiplier on the directional light's colour (0..100)."),
       {}},
      {option::kEnvironment,
       QStringLiteral("name|file"),
       enumNames(core::allBuiltInEnvironments(), core::builtInEnvironmentName) +
           QStringLiteral(" (built in), or an equirectangular EXR or Radiance HDR file: the "
                          "image-based light of pbr shading and what --background shows. "
                          "Default studio."),
       {}},
      {option::kEnvironmentIntensity,
       QStringLiteral("X"),
       QStringLiteral("Multiplier on the environment's radiance (0..16, default 1)."),
       {}},
      {option::kEnvironmentRotation,
       QStringLiteral("deg"),
       QStringLiteral("Turns the environment about the vertical axis (degrees)."),
       {}},
      {option::kBackground,
       QStringLiteral("name"),
       enumNames(core::allBackgrounds(), core::backgroundName) +
           QStringLiteral(": a plain dark gradient, the environment, or the environment "
                          "blurred. Default color."),
       {}},
      {option::kExposure,
       QStringLiteral("EV"),
       QStringLiteral("Exposure of the shading view in stops (-10..10); +1 doubles it."),
       {}},
      {option::kTonemap,
       QStringLiteral("name"),
       enumNames(core::allToneMappers(), core::toneMapperName) +
           QStringLiteral(": none clips at 1, neutral is Khronos PBR Neutral, aces is ACES "
                          "filmic. EXR output is the radiance before exposure and tone "
                          "mapping."),
       {}},
  };
}

std::optional<int> applyLightingOptions(const QCommandLineParser& parser,
                                        const core::ViewState& presetView,
                                        const QString& presetPath, renderer::RenderView& view) {
  if (presetView.light)
    view.light = *presetView.light;
  if (presetView.display)
    view.display = *presetView.display;
  if (presetView.environment)
    view.environment = *presetView.environment;
  const auto intensity = numberOption(parser, option::kLightIntensity, view.light.intensity);
  if (!intensity)
    return kExitUsage;
  if (*intensity < 0.0 || *intensity > kMaxLightIntensity) {
    printError(QStringLiteral("--light-intensity must be within 0..%1").arg(kMaxLightIntensity));
    return kExitUsage;
  }
  view.light.intensity = float(*intensity);
  if (auto exit = applyDisplay(parser, view.display))
    return exit;
  return applyEnvironment(parser, presetView.environment ? presetPath : QString(),
                          view.environment);
}

}  // namespace relief::cli
