// MapFileLoader; see MapFileLoader.h.
#include "ui/window/MapFileLoader.h"

#include "core/compression/MapFile.h"
#include "core/compression/TextureFile.h"
#include "core/image/ImageFileTypes.h"
#include "core/material/MapContent.h"
#include "core/preset/OrmTexture.h"
#include "ui/QtText.h"
#include "ui/document/MaterialDocument.h"
#include "ui/settings/AppSettings.h"

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
  const QString fileName = QFileInfo(path).fileName();
  const QString question =
      core::isSpecularFileName(fileName.toStdString())
          ? tr("%1 looks like a specular or gloss map, which Relief's materials have no slot "
               "for (roughness is gloss inverted).\nUse it as:")
                .arg(fileName)
          : tr("%1 does not say which map it is.\nUse it as:").arg(fileName);
  bool ok = false;
  const QString chosen =
      QInputDialog::getItem(m_parent, tr("Which map is this?"), question, labels, 0, false, &ok);
  if (!ok)
    return std::nullopt;
  return core::kAllMapSlots[std::size_t(labels.indexOf(chosen))];
}

bool MapFileLoader::load(const QString& path, std::optional<core::MapSlot> slot) {
  const QString fileName = QFileInfo(path).fileName();
  if (!slot && core::isOrmFileName(fileName.toStdString()))
    return loadOrm(path);
  const std::optional<core::MapSlot> named =
      slot ? slot : core::guessMapSlotFromFileName(fileName.toStdString());
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<core::Image> image = core::loadMapFile(path.toStdString());
  QApplication::restoreOverrideCursor();
  if (!image) {
    QMessageBox::warning(m_parent, tr("Cannot load map"), QString::fromStdString(image.error()));
    return false;
  }
  // A file whose name says nothing, or says colour, but whose texels are a normal map's (a
  // blue "wall_c.png") goes to the normal slot: a normal map shown as colour looks broken.
  QString why;
  if (!slot && (!named || *named == core::MapSlot::Color) &&
      core::looksLikeNormalMap(image.value())) {
    slot = core::MapSlot::Normal;
    why = tr(" (its texels are a normal map's: bluish, unit vectors)");
  }
  if (!slot)
    slot = named;
  if (!slot)
    slot = askForSlot(path);
  if (!slot)
    return false;
  m_document->setMap(*slot, std::make_shared<core::Image>(std::move(image).value()),
                     QFileInfo(path).absoluteFilePath());
  settings::setLastFolder(QStringLiteral("map"), QFileInfo(path).absolutePath());
  m_lastLoaded =
      tr("%1 as the %2 map").arg(fileName, toQString(core::mapSlotLabel(*slot)).toLower()) + why;
  Q_EMIT statusMessage(tr("Loaded %1").arg(m_lastLoaded), 5000);
  return true;
}

int MapFileLoader::loadSet(const QStringList& paths) {
  if (paths.size() == 1)
    return load(paths.front()) ? 1 : 0;
  // A set (Open Map with several files, or a drop) is one undo step, reported in one message.
  m_document->undoStack()->beginMacro(tr("Load %1 maps").arg(paths.size()));
  QStringList loaded;
  for (const QString& path : paths) {
    if (load(path))
      loaded << m_lastLoaded;
  }
  m_document->undoStack()->endMacro();
  if (!loaded.isEmpty())
    Q_EMIT statusMessage(tr("Loaded %1").arg(loaded.join(QStringLiteral("; "))), 8000);
  return int(loaded.size());
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
  m_lastLoaded =
      tr("%1 as the ambient occlusion (R), roughness (G) and metallic (B) maps").arg(fileName);
  Q_EMIT statusMessage(tr("Loaded %1").arg(m_lastLoaded), 5000);
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
  const QString folder = settings::lastFolder(QStringLiteral("map"));
  if (slot) {
    const QString title = tr("Load %1 map").arg(toQString(core::mapSlotLabel(*slot)).toLower());
    const QString path = QFileDialog::getOpenFileName(m_parent, title, folder, fileFilter());
    if (!path.isEmpty())
      load(path, slot);
    return;
  }
  // Open Map takes a whole set at once: each file goes to the slot its name or texels say.
  const QStringList paths =
      QFileDialog::getOpenFileNames(m_parent, tr("Open maps"), folder, fileFilter());
  if (!paths.isEmpty())
    loadSet(paths);
}

}  // namespace relief::ui::inline window
