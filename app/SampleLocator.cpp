// SampleLocator; see SampleLocator.h.
#include "SampleLocator.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace relief::app {

QString samplesDirectory() {
  QStringList candidates;
  const QString fromEnvironment = qEnvironmentVariable("RELIEF_SAMPLES");
  if (!fromEnvironment.isEmpty())
    candidates << fromEnvironment;
  const QString appDir = QCoreApplication::applicationDirPath();
  candidates << appDir + QStringLiteral("/" RELIEF_INSTALLED_SAMPLES_RELATIVE)
             << QStringLiteral(RELIEF_SOURCE_SAMPLES_DIR);
  for (const QString& candidate : candidates) {
    if (QFileInfo(candidate).isDir())
      return QDir(candidate).absolutePath();
  }
  return {};
}

QString defaultSamplePreset() {
  const QString directory = samplesDirectory();
  if (directory.isEmpty())
    return {};
  const QString preset = directory + QStringLiteral("/bricks/bricks.relief");
  return QFileInfo::exists(preset) ? preset : QString();
}

}  // namespace relief::app
