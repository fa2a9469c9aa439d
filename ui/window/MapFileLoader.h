// MapFileLoader: puts image files into the material's map slots for the main window (File >
// Open Map, a slot's Load button, drops). The slot is the one asked for, else the one the file
// name hints at (_normal, _height, ...; _orm and _arm fill three slots), else the one the user
// picks; a file that cannot be read is reported in a dialog naming it, and the document is
// left as it was.
#pragma once

#include "core/material/MapSlot.h"
#include "ui/Forward.h"

#include <QObject>
#include <QString>

#include <optional>

class QWidget;

namespace relief::ui::inline window {

class MapFileLoader : public QObject {
  Q_OBJECT

 public:
  MapFileLoader(MaterialDocument* document, QWidget* dialogParent);

  // Returns false (after telling the user) when the file cannot be used or the user cancels.
  bool load(const QString& path, std::optional<core::MapSlot> slot = std::nullopt);
  // Asks for a file (starting in the last map folder), then loads it.
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
};

}  // namespace relief::ui::inline window
