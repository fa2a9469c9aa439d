// MapFileLoader: puts image files into the material's map slots for the main window (File >
// Open Map, a slot's Load button, drops). The slot is the one asked for, else the one the file
// name hints at (_normal, _height, game data's _n, _z, _d ...; _orm and _arm fill three slots),
// else the normal slot when its texels are a normal map's, else the one the user picks; a file
// that cannot be read is reported in a dialog naming it, and the document is left as it was.
#pragma once

#include "core/material/MapSlot.h"
#include "ui/Forward.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <optional>

class QWidget;

namespace relief::ui::inline window {

class MapFileLoader : public QObject {
  Q_OBJECT

 public:
  MapFileLoader(MaterialDocument* document, QWidget* dialogParent);

  // Returns false (after telling the user) when the file cannot be used or the user cancels.
  bool load(const QString& path, std::optional<core::MapSlot> slot = std::nullopt);
  // Several files as one undo step (a set opened or dropped together); returns how many loaded.
  int loadSet(const QStringList& paths);
  // Asks for a file for `slot`, or for any number of files without one (starting in the last
  // map folder), then loads them.
  void choose(std::optional<core::MapSlot> slot);
  // An ORM texture (R occlusion, G roughness, B metallic: glTF's and Unreal's packing) into
  // the AO, roughness and metallic slots, as one undo step; false (after telling the user)
  // when it cannot be read or has fewer than three channels.
  bool loadOrm(const QString& path);
  void chooseOrm();

  static bool isImageFile(const QString& path);
  static QString fileFilter();  // for file dialogs

 Q_SIGNALS:
  void statusMessage(const QString& message, int timeoutMs);

 private:
  std::optional<core::MapSlot> askForSlot(const QString& path);

  MaterialDocument* m_document;
  QWidget* m_parent;
  QString m_lastLoaded;  // "file as the normal map", for a set's summary
};

}  // namespace relief::ui::inline window
