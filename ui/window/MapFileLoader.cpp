// MapFileLoader; see MapFileLoader.h.
#include "ui/window/MapFileLoader.h"

#include "core/compression/MapFile.h"
#include "core/compression/TextureFile.h"
#include "core/image/ImageFileTypes.h"
#include "core/material/OrmTexture.h"
#include "ui/document/MaterialDocument.h"
#include "ui/window/AppSettings.h"
#include "ui/window/QtText.h"

#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>
#include <QStringList>

namespace relief::ui::inline window {
MapFileLoader::MapFileLoader(MaterialDocument* document, QWidget* dialogParent)
    : QObject(dialogParent), m_document(document), m_parent(dialogParent) {}

// Images, and compressed textures (DDS, KTX2) read as the map they hold (core::loadMapFile).
bool MapFileLoader::isImageFile(const QString& path) {
  return core::imageFileTypeForPath(path.toStdString()) != nullptr ||
         core::containerForPath(path.toStdString()).has_value();
}

QString MapFileLoader::fileFilter() {
  QStringList patterns;
  for (const core::ImageFileType& type : core::imageFileTypes())
    patterns << QStringLiteral("*.") + toQString(type.extension);
  for (core::TextureContainer container :
       {core::TextureContainer::Dds, core::TextureContainer::Ktx2})
    patterns << QStringLiteral("*.") + toQString(core::textureContainerInfo(container).extension);
  return tr("Maps (%1);;All files (*)").arg(patterns.join(QLatin1Char(' ')));
}

std::optional<core::MapSlot> MapFileLoader::askForSlot(const QString& path) {
  QStringList labels;
  for (core::MapSlot candidate : core::kAllMapSlots)
    labels << toQString(core::mapSlotLabel(candidate));
  bool ok = false;
  const QString chosen = QInputDialog::getItem(
      m_parent, tr("Which map is this?"),
      tr("%1 does not say which map it is.\nUse it as:").arg(QFileInfo(path).fileName()), labels, 0,
      false, &ok);
  if (!ok)
    return std::nullopt;
  return core::kAllMapSlots[std::size_t(labels.indexOf(chosen))];
}

bool MapFileLoader::load(const QString& path, std::optional<core::MapSlot> slot) {
  if (!slot && core::isOrmFileName(QFileInfo(path).fileName().toStdString()))
    return loadOrm(path);
  if (!slot)
    slot = core::guessMapSlotFromFileName(QFileInfo(path).fileName().toStdString());
  if (!slot)
    slot = askForSlot(path);
  if (!slot)
    return false;
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<core::Image> image = core::loadMapFile(path.toStdString());
  QApplication::restoreOverrideCursor();
  if (!image) {
    QMessageBox::warning(m_parent, tr("Cannot load map"), QString::fromStdString(image.error()));
    return false;
  }
  m_document->setMap(*slot, std::make_shared<core::Image>(std::move(image).value()),
                     QFileInfo(path).absoluteFilePath());
  settings::setLastFolder(QStringLiteral("map"), QFileInfo(path).absolutePath());
  Q_EMIT statusMessage(
      tr("Loaded %1 as the %2 map")
          .arg(QFileInfo(path).fileName(), toQString(core::mapSlotLabel(*slot)).toLower()),
      5000);
  return true;
}

bool MapFileLoader::loadOrm(const QString& path) {
  const QString fileName = QFileInfo(path).fileName();
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<std::vector<core::ChannelMap>> maps = core::loadOrmTexture(path.toStdString());
  QApplication::restoreOverrideCursor();
  if (!maps) {
    QMessageBox::warning(m_parent, tr("Cannot load ORM texture"),
                         QString::fromStdString(maps.error()));
    return false;
  }
  m_document->undoStack()->beginMacro(tr("Load ORM texture (%1)").arg(fileName));
  for (core::ChannelMap& map : maps.value()) {
    m_document->setMap(map.slot, std::make_shared<core::Image>(std::move(map.image)),
                       QFileInfo(path).absoluteFilePath(), map.channel);
  }
  m_document->undoStack()->endMacro();
  settings::setLastFolder(QStringLiteral("map"), QFileInfo(path).absolutePath());
  Q_EMIT statusMessage(
      tr("Loaded %1 as the ambient occlusion (R), roughness (G) and metallic (B) maps")
          .arg(fileName),
      5000);
  return true;
}

void MapFileLoader::chooseOrm() {
  const QString path = QFileDialog::getOpenFileName(
      m_parent, tr("Load ORM texture (R occlusion, G roughness, B metallic)"),
      settings::lastFolder(QStringLiteral("map")), fileFilter());
  if (!path.isEmpty())
    loadOrm(path);
}

void MapFileLoader::choose(std::optional<core::MapSlot> slot) {
  const QString title =
      slot ? tr("Load %1 map").arg(toQString(core::mapSlotLabel(*slot)).toLower()) : tr("Open map");
  const QString path = QFileDialog::getOpenFileName(
      m_parent, title, settings::lastFolder(QStringLiteral("map")), fileFilter());
  if (!path.isEmpty())
    load(path, slot);
}

}  // namespace relief::ui::inline window
