// CroppedSample; see CroppedSample.h.
#include "support/CroppedSample.h"

#include "core/image/ImageIO.h"
#include "support/TestPaths.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

#include <gtest/gtest.h>

#include <filesystem>

namespace relief::test {

std::string croppedSamplePreset(const std::string& sample, int size, const std::string& folder) {
  std::filesystem::create_directories(folder);
  QFile file(QString::fromStdString(samplePreset(sample)));
  EXPECT_TRUE(file.open(QIODevice::ReadOnly));
  QJsonObject preset = QJsonDocument::fromJson(file.readAll()).object();
  QJsonObject maps = preset.value(QStringLiteral("maps")).toObject();
  for (const QString& slot : maps.keys()) {
    QJsonObject map = maps.value(slot).toObject();
    const std::string name = map.value(QStringLiteral("path")).toString().toStdString();
    core::Result<core::Image> full = core::loadImage(sourcePath("samples/" + sample + "/" + name));
    EXPECT_TRUE(full.ok()) << full.error();
    if (!full)
      continue;
    core::Image cut(size, size, full->channels(), full->colorSpace());
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        for (int c = 0; c < full->channels(); ++c)
          cut.at(x, y, c) = full->at(x, y, c);
      }
    }
    EXPECT_TRUE(core::saveImage(cut, folder + "/" + name, core::SampleFormat::UInt16).ok());
    maps.insert(slot, map);  // the same relative path, now beside the cut preset
  }
  preset.insert(QStringLiteral("maps"), maps);
  const std::string path = folder + "/" + sample + "_cut.relief";
  QFile out(QString::fromStdString(path));
  EXPECT_TRUE(out.open(QIODevice::WriteOnly));
  out.write(QJsonDocument(preset).toJson());
  return path;
}

}  // namespace relief::test
