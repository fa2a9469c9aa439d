// AppSettings; see AppSettings.h.
#include "ui/settings/AppSettings.h"

#include "core/mesh/MeshPrimitives.h"
#include "core/shading/EnvironmentMaps.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

#include <algorithm>

namespace relief::ui::settings {
namespace {

const QString kRecent = QStringLiteral("recentFiles");
const QString kFolders = QStringLiteral("folders/");
const QString kAnyFolder = QStringLiteral("folders/any");
const QString kDialogs = QStringLiteral("dialogs/");

}  // namespace

QStringList recentFiles() {
  QStringList files = QSettings().value(kRecent).toStringList();
  files.erase(std::remove_if(files.begin(), files.end(),
                             [](const QString& path) { return !QFileInfo::exists(path); }),
              files.end());
  return files;
}

void addRecentFile(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  QStringList files = QSettings().value(kRecent).toStringList();
  files.removeAll(absolute);
  files.prepend(absolute);
  while (files.size() > kMaxRecentFiles)
    files.removeLast();
  QSettings().setValue(kRecent, files);
}

void removeRecentFile(const QString& path) {
  QStringList files = QSettings().value(kRecent).toStringList();
  files.removeAll(QFileInfo(path).absoluteFilePath());
  QSettings().setValue(kRecent, files);
}

QString dialogChoice(const QString& key) {
  return QSettings().value(kDialogs + key).toString();
}

void setDialogChoice(const QString& key, const QString& value) {
  QSettings().setValue(kDialogs + key, value);
}

QString lastFolder(const QString& purpose, bool orAny) {
  const QSettings settings;
  QStringList keys{kFolders + purpose};
  if (orAny)
    keys << kAnyFolder;
  for (const QString& key : keys) {
    const QString folder = settings.value(key).toString();
    if (!folder.isEmpty() && QFileInfo(folder).isDir())
      return folder;
  }
  const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
  return QFileInfo(documents).isDir() ? documents : QDir::homePath();
}

void setLastFolder(const QString& purpose, const QString& folder) {
  QSettings settings;
  settings.setValue(kFolders + purpose, folder);
  settings.setValue(kAnyFolder, folder);
}

int autosaveMinutes() {
  return std::clamp(QSettings().value(QStringLiteral("preferences/autosaveMinutes"), 2).toInt(), 0,
                    60);
}

void setAutosaveMinutes(int minutes) {
  QSettings().setValue(QStringLiteral("preferences/autosaveMinutes"), minutes);
}

bool nativeCompressedUploads() {
  return QSettings().value(QStringLiteral("preferences/nativeCompressedUploads"), true).toBool();
}

void setNativeCompressedUploads(bool native) {
  QSettings().setValue(QStringLiteral("preferences/nativeCompressedUploads"), native);
}

bool openSampleOnStart() {
  return QSettings().value(QStringLiteral("preferences/openSampleOnStart"), true).toBool();
}

void setOpenSampleOnStart(bool open) {
  QSettings().setValue(QStringLiteral("preferences/openSampleOnStart"), open);
}

QString defaultMesh() {
  const QString mesh =
      QSettings()
          .value(QStringLiteral("preferences/defaultMesh"), QStringLiteral("plane"))
          .toString();
  return core::findPrimitiveShape(mesh.toStdString()) ? mesh : QStringLiteral("plane");
}

void setDefaultMesh(const QString& mesh) {
  QSettings().setValue(QStringLiteral("preferences/defaultMesh"), mesh);
}

core::DirectionalLight viewportLight() {
  QSettings settings;
  settings.beginGroup(QStringLiteral("viewport/light"));
  core::DirectionalLight light;
  light.azimuthDeg = settings.value(QStringLiteral("azimuth"), light.azimuthDeg).toFloat();
  light.elevationDeg = std::clamp(
      settings.value(QStringLiteral("elevation"), light.elevationDeg).toFloat(), -90.0f, 90.0f);
  light.intensity = std::clamp(
      settings.value(QStringLiteral("intensity"), light.intensity).toFloat(), 0.0f, 100.0f);
  light.ambient =
      std::clamp(settings.value(QStringLiteral("ambient"), light.ambient).toFloat(), 0.0f, 1.0f);
  const QList<QVariant> color = settings.value(QStringLiteral("color")).toList();
  if (color.size() == 3) {
    for (int i = 0; i < 3; ++i)
      light.color[i] = std::clamp(color[i].toFloat(), 0.0f, 16.0f);
  }
  return light;
}

void setViewportLight(const core::DirectionalLight& light) {
  QSettings settings;
  settings.beginGroup(QStringLiteral("viewport/light"));
  settings.setValue(QStringLiteral("azimuth"), light.azimuthDeg);
  settings.setValue(QStringLiteral("elevation"), light.elevationDeg);
  settings.setValue(QStringLiteral("intensity"), light.intensity);
  settings.setValue(QStringLiteral("ambient"), light.ambient);
  settings.setValue(QStringLiteral("color"),
                    QList<QVariant>{light.color.r, light.color.g, light.color.b});
}

core::DisplayTransform viewportDisplay() {
  QSettings settings;
  settings.beginGroup(QStringLiteral("viewport/display"));
  core::DisplayTransform display;
  display.exposureEv =
      std::clamp(settings.value(QStringLiteral("exposure"), display.exposureEv).toFloat(),
                 core::DisplayTransform::kMinExposureEv, core::DisplayTransform::kMaxExposureEv);
  const std::string toneMapper =
      settings.value(QStringLiteral("toneMapping")).toString().toStdString();
  if (const auto found = core::findToneMapper(toneMapper))
    display.toneMapper = *found;
  return display;
}

void setViewportDisplay(const core::DisplayTransform& display) {
  QSettings settings;
  settings.beginGroup(QStringLiteral("viewport/display"));
  settings.setValue(QStringLiteral("exposure"), display.exposureEv);
  settings.setValue(QStringLiteral("toneMapping"),
                    QString::fromUtf8(core::toneMapperName(display.toneMapper)));
}

core::Environment viewportEnvironment() {
  QSettings settings;
  settings.beginGroup(QStringLiteral("viewport/environment"));
  core::Environment environment;
  const QString source = settings.value(QStringLiteral("source")).toString();
  if (core::findBuiltInEnvironment(source.toStdString()) || QFileInfo::exists(source))
    environment.source = source.toStdString();
  environment.intensity =
      std::clamp(settings.value(QStringLiteral("intensity"), environment.intensity).toFloat(), 0.0f,
                 core::Environment::kMaxIntensity);
  environment.rotationDeg =
      std::clamp(settings.value(QStringLiteral("rotation"), environment.rotationDeg).toFloat(),
                 -360.0f, 360.0f);
  const std::string background =
      settings.value(QStringLiteral("background")).toString().toStdString();
  if (const auto found = core::findBackground(background))
    environment.background = *found;
  return environment;
}

void setViewportEnvironment(const core::Environment& environment) {
  QSettings settings;
  settings.beginGroup(QStringLiteral("viewport/environment"));
  settings.setValue(QStringLiteral("source"), QString::fromStdString(environment.source));
  settings.setValue(QStringLiteral("intensity"), environment.intensity);
  settings.setValue(QStringLiteral("rotation"), environment.rotationDeg);
  settings.setValue(QStringLiteral("background"),
                    QString::fromUtf8(core::backgroundName(environment.background)));
}

}  // namespace relief::ui::settings
