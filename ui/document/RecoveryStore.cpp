// RecoveryStore; see RecoveryStore.h.
#include "ui/document/RecoveryStore.h"

#include "ui/tasks/BackgroundTask.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QUuid>

#include <algorithm>

namespace relief::ui::inline document {
namespace {

const QString kPresetName = QStringLiteral("autosave.relief");
const QString kLockName = QStringLiteral("session.lock");

}  // namespace

const QString& RecoveryStore::recoveryKey() {
  static const QString key = QStringLiteral("reliefRecovery");
  return key;
}

QString RecoveryStore::recoveryRoot() {
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
         QStringLiteral("/recovery");
}

RecoveryStore::RecoveryStore(QObject* parent)
    : QObject(parent), m_writer(new BackgroundTask(this)) {
  m_folder = recoveryRoot() + QLatin1Char('/') + QUuid::createUuid().toString(QUuid::WithoutBraces);
  QDir().mkpath(m_folder);
  m_lock = std::make_unique<QLockFile>(m_folder + QLatin1Char('/') + kLockName);
  m_lock->tryLock(0);
}

RecoveryStore::~RecoveryStore() {
  m_pending.reset();
  m_writer->waitForFinished();
  m_lock->unlock();
  QDir(m_folder).removeRecursively();
}

void RecoveryStore::autosave(const core::Preset& preset, const QString& originalPath) {
  core::Preset copy = preset;  // images are shared, so this is cheap
  copy.preserved.insert(
      recoveryKey(),
      QJsonObject{{QStringLiteral("originalPath"), originalPath},
                  {QStringLiteral("savedAt"), QDateTime::currentDateTime().toString(Qt::ISODate)}});
  if (m_writer->isRunning()) {
    m_pending = std::move(copy);
    return;
  }
  startWrite(std::move(copy));
}

void RecoveryStore::startWrite(core::Preset preset) {
  // Maps from files are referenced where they are; only generated maps are written here.
  const std::string path = (m_folder + QLatin1Char('/') + kPresetName).toStdString();
  // Writes follow one another (never two at once on the same files); the newest state waits.
  using Saved = core::Result<core::SavedPreset>;
  m_writer->run<Saved>([preset = std::move(preset),
                        path](const core::WorkControl&) { return core::savePreset(preset, path); },
                       [this](Saved&& saved) {
                         if (!saved && !m_reportedFailure) {
                           m_reportedFailure = true;
                           Q_EMIT autosaveFailed(QString::fromStdString(saved.error()));
                         }
                         if (m_pending) {
                           core::Preset next = std::move(*m_pending);
                           m_pending.reset();
                           startWrite(std::move(next));
                         }
                       });
}

void RecoveryStore::clear() {
  m_pending.reset();
  m_writer->waitForFinished();
  QDir folder(m_folder);
  for (const QString& name : folder.entryList(QDir::Files)) {
    if (name != kLockName)
      folder.remove(name);
  }
}

bool RecoveryStore::hasAutosave() const {
  return QFileInfo::exists(m_folder + QLatin1Char('/') + kPresetName);
}

std::vector<RecoverableWork> RecoveryStore::abandonedWork() {
  std::vector<RecoverableWork> found;
  const QDir root(recoveryRoot());
  for (const QFileInfo& session : root.entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot)) {
    QLockFile lock(session.absoluteFilePath() + QLatin1Char('/') + kLockName);
    // A live session holds its lock; tryLock succeeds only for a dead one (QLockFile checks
    // that the owning process is gone) or a folder without a lock.
    if (!lock.tryLock(0))
      continue;
    lock.unlock();
    const QString preset = session.absoluteFilePath() + QLatin1Char('/') + kPresetName;
    if (!QFileInfo::exists(preset)) {
      QDir(session.absoluteFilePath()).removeRecursively();
      continue;
    }
    RecoverableWork work{session.absoluteFilePath(), preset, QString(),
                         QFileInfo(preset).lastModified()};
    QFile file(preset);
    if (file.open(QIODevice::ReadOnly)) {
      const QJsonObject info =
          QJsonDocument::fromJson(file.readAll()).object().value(recoveryKey()).toObject();
      work.originalPath = info.value(QStringLiteral("originalPath")).toString();
    }
    found.push_back(work);
  }
  std::sort(found.begin(), found.end(), [](const RecoverableWork& a, const RecoverableWork& b) {
    return a.savedAt > b.savedAt;
  });
  return found;
}

void RecoveryStore::discard(const RecoverableWork& work) {
  QDir(work.folder).removeRecursively();
}

}  // namespace relief::ui::inline document
