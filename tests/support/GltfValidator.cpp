// GltfValidator; see GltfValidator.h.
#include "GltfValidator.h"

#include "TestPaths.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>

#include <filesystem>

namespace relief::test {

GltfValidation validateGltf(const std::string& gltfPath) {
  GltfValidation result;
  const std::string folder = binaryPath("gltf-validator");
  const std::string module = folder + "/node_modules/gltf-validator";
  if (!std::filesystem::exists(module + "/package.json")) {
    QFile reason(QString::fromStdString(folder + "/UNAVAILABLE"));
    if (reason.open(QIODevice::ReadOnly)) {
      result.unavailableReason = reason.readAll().trimmed().toStdString();
    } else {
      result.unavailableReason =
          "gltf-validator is not installed in " + folder +
          " (run tools/gltf-validator/setup.sh with this build folder; make test does)";
    }
    return result;
  }
  const QString node = QStandardPaths::findExecutable(QStringLiteral("node"));
  if (node.isEmpty()) {
    result.unavailableReason = "node is not on PATH";
    return result;
  }
  result.available = true;
  QProcess process;
  process.start(node, {QString::fromStdString(sourcePath("tools/gltf-validator/validate.js")),
                       QString::fromStdString(std::filesystem::absolute(module).string()),
                       QString::fromStdString(gltfPath)});
  process.waitForFinished(120000);
  const QByteArray output = process.readAllStandardOutput();
  result.report = output.toStdString() + process.readAllStandardError().toStdString();
  const QJsonObject issues =
      QJsonDocument::fromJson(output).object().value(QStringLiteral("issues")).toObject();
  if (issues.isEmpty()) {
    result.errors = -1;  // no report: node failed
    return result;
  }
  result.errors = issues.value(QStringLiteral("numErrors")).toInt();
  result.warnings = issues.value(QStringLiteral("numWarnings")).toInt();
  return result;
}

}  // namespace relief::test
