// RecoveryStore: autosave and crash recovery. Each running editor owns a session folder under
// AppDataLocation/recovery, marked by a lock file, and autosaves unsaved work there as a preset
// (with any generated maps beside it). A clean exit removes the folder; a folder whose lock
// is stale (its process died) holds work to offer on the next start.
#pragma once

#include "core/preset/MaterialPreset.h"
#include "ui/Forward.h"

#include <QDateTime>
#include <QLockFile>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace relief::ui::inline document {

struct RecoverableWork {
  QString folder;        // the crashed session's folder
  QString presetPath;    // the autosaved preset in it
  QString originalPath;  // the file the work belonged to; empty for an unsaved document
  QDateTime savedAt;
};

class RecoveryStore : public QObject {
  Q_OBJECT

 public:
  explicit RecoveryStore(QObject* parent = nullptr);
  ~RecoveryStore() override;  // a clean exit: the session's folder goes

  // Writes the preset in the background (a large generated map takes a moment to encode); if
  // a write is still running, this one follows it. Failures are reported once.
  void autosave(const core::Preset& preset, const QString& originalPath);
  // The work was saved or discarded: nothing to recover any more.
  void clear();
  bool hasAutosave() const;
  QString sessionFolder() const { return m_folder; }

  // Work left by sessions that did not exit cleanly, newest first.
  static std::vector<RecoverableWork> abandonedWork();
  static void discard(const RecoverableWork& work);
  // The key autosaves carry in the preset (dropped when the work is recovered).
  static const QString& recoveryKey();

 Q_SIGNALS:
  void autosaveFailed(const QString& message);

 private:
  static QString recoveryRoot();

  QString m_folder;
  std::unique_ptr<QLockFile> m_lock;
  void startWrite(core::Preset preset);

  BackgroundTask* m_writer;               // one autosave write at a time
  std::optional<core::Preset> m_pending;  // the newest state, waiting for the running write
  bool m_reportedFailure = false;
};

}  // namespace relief::ui::inline document
