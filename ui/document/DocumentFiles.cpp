// DocumentFiles; see DocumentFiles.h.
#include "ui/document/DocumentFiles.h"

#include "ui/document/MaterialDocument.h"
#include "ui/document/RecoveryStore.h"
#include "ui/document/ViewDocument.h"
#include "ui/settings/AppSettings.h"

#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>

namespace relief::ui::inline document {
namespace {

const QString kPresetFilter = QObject::tr("Relief presets (*.relief)");

QStringList warningLines(const std::vector<std::string>& warnings) {
  QStringList lines;
  for (const std::string& warning : warnings)
    lines << QString::fromStdString(warning);
  return lines;
}

}  // namespace

DocumentFiles::DocumentFiles(MaterialDocument* document, ViewDocument* view, QWidget* dialogParent)
    : QObject(dialogParent),
      m_document(document),
      m_parent(dialogParent),
      m_view(view),
      m_recovery(new RecoveryStore(this)) {
  connect(&m_autosaveTimer, &QTimer::timeout, this, &DocumentFiles::autosaveNow);
  connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
    if (clean)
      m_recovery->clear();  // back at the saved state: nothing to recover
  });
  connect(m_recovery, &RecoveryStore::autosaveFailed, this, [this](const QString& message) {
    Q_EMIT statusMessage(tr("Autosave failed: %1").arg(message), 20000);
  });
  updateAutosaveInterval();
}

DocumentFiles::~DocumentFiles() = default;

void DocumentFiles::updateAutosaveInterval() {
  const int minutes = settings::autosaveMinutes();
  if (minutes <= 0) {
    m_autosaveTimer.stop();
    return;
  }
  m_autosaveTimer.start(minutes * 60 * 1000);
}

void DocumentFiles::autosaveNow() {
  if (m_document->isModified())
    m_recovery->autosave(m_document->toPreset(m_view->viewState()), m_document->filePath());
}

QString DocumentFiles::displayName() const {
  if (!m_document->filePath().isEmpty())
    return QFileInfo(m_document->filePath()).fileName();
  if (!m_document->material().name().empty())
    return QString::fromStdString(m_document->material().name());
  return tr("untitled");
}

bool DocumentFiles::maybeSave(const QString& reason) {
  if (!m_document->isModified())
    return true;
  QMessageBox box(QMessageBox::Warning, tr("Unsaved changes"),
                  tr("“%1” has changes that are not saved.").arg(displayName()),
                  QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, m_parent);
  box.setObjectName(QStringLiteral("unsavedChangesPrompt"));
  box.setInformativeText(tr("Save them before %1?").arg(reason));
  box.setDefaultButton(QMessageBox::Save);
  switch (box.exec()) {
    case QMessageBox::Save:
      return save();
    case QMessageBox::Discard:
      return true;
    default:
      return false;
  }
}

bool DocumentFiles::newDocument() {
  if (!maybeSave(tr("starting a new material")))
    return false;
  m_document->reset(core::Material(), QString());
  m_recovery->clear();
  core::ViewState fresh;
  fresh.mesh = settings::defaultMesh().toStdString();
  showView(fresh);
  Q_EMIT statusMessage(tr("New material: load or generate maps to begin"), 5000);
  return true;
}

bool DocumentFiles::openWithPrompt() {
  const QString path = QFileDialog::getOpenFileName(
      m_parent, tr("Open preset"), settings::lastFolder(QStringLiteral("preset")), kPresetFilter);
  return !path.isEmpty() && open(path);
}

bool DocumentFiles::open(const QString& path) {
  return maybeSave(tr("opening another preset")) && openFile(path);
}

bool DocumentFiles::openFile(const QString& path) {
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<core::LoadedPreset> loaded = core::loadPreset(path.toStdString());
  QApplication::restoreOverrideCursor();
  if (!loaded) {
    QMessageBox::warning(m_parent, tr("Cannot open preset"),
                         QString::fromStdString(loaded.error()));
    settings::removeRecentFile(path);
    return false;
  }
  const QString absolute = QFileInfo(path).absoluteFilePath();
  const core::ViewState view = loaded->preset.view;
  m_document->reset(std::move(loaded->preset), absolute);
  m_recovery->clear();
  showView(view);
  settings::addRecentFile(absolute);
  settings::setLastFolder(QStringLiteral("preset"), QFileInfo(absolute).absolutePath());
  if (!loaded->warnings.empty()) {
    // A missing map or a clamped value matters: say so where it cannot be missed.
    QMessageBox box(
        QMessageBox::Warning, tr("Opened with problems"),
        tr("%1 opened, but %n problem(s) need attention.", nullptr, int(loaded->warnings.size()))
            .arg(QFileInfo(path).fileName()),
        QMessageBox::Ok, m_parent);
    box.setObjectName(QStringLiteral("presetProblems"));
    box.setDetailedText(warningLines(loaded->warnings).join(QLatin1Char('\n')));
    box.setInformativeText(warningLines(loaded->warnings).mid(0, 3).join(QLatin1Char('\n')));
    box.exec();
  }
  if (loaded->fileVersion != core::kPresetVersion) {
    Q_EMIT statusMessage(tr("Opened %1 (format version %2; saving writes version %3)")
                             .arg(QFileInfo(path).fileName())
                             .arg(loaded->fileVersion)
                             .arg(core::kPresetVersion),
                         10000);
  } else {
    Q_EMIT statusMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), 5000);
  }
  return true;
}

bool DocumentFiles::isProtected(const QString& path) const {
  return !m_protectedFolder.isEmpty() &&
         QFileInfo(path).absoluteFilePath().startsWith(QDir(m_protectedFolder).absolutePath() +
                                                       QLatin1Char('/'));
}

bool DocumentFiles::save() {
  const QString path = m_document->filePath();
  if (path.isEmpty() || isProtected(path))
    return saveAs();
  return saveTo(path);
}

bool DocumentFiles::saveAs() {
  // Not beside the bundled samples: the artist's version goes where their presets go.
  QString folder = settings::lastFolder(QStringLiteral("preset"));
  if (isProtected(folder + QStringLiteral("/x")))
    folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
  const QString suggested = folder + QLatin1Char('/') +
                            QFileInfo(displayName()).completeBaseName() + QStringLiteral(".relief");
  for (;;) {
    QString path =
        QFileDialog::getSaveFileName(m_parent, tr("Save preset as"), suggested, kPresetFilter);
    if (path.isEmpty())
      return false;
    if (QFileInfo(path).suffix().isEmpty())
      path += QStringLiteral(".relief");
    if (!isProtected(path))
      return saveTo(path);
    QMessageBox::information(m_parent, tr("Save preset as"),
                             tr("%1 is one of the bundled samples, which stay as shipped. Save "
                                "your version in another folder.")
                                 .arg(QFileInfo(path).fileName()));
  }
}

bool DocumentFiles::saveTo(const QString& path) {
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<core::SavedPreset> saved = m_document->save(path, m_view->viewState());
  QApplication::restoreOverrideCursor();
  if (!saved) {
    QMessageBox::critical(m_parent, tr("Cannot save"),
                          tr("%1\n\nThe previous file, if any, is unchanged.")
                              .arg(QString::fromStdString(saved.error())));
    return false;
  }
  m_recovery->clear();
  settings::addRecentFile(path);
  settings::setLastFolder(QStringLiteral("preset"), QFileInfo(path).absolutePath());
  QString message = tr("Saved %1").arg(QFileInfo(path).fileName());
  if (!saved->writtenMaps.empty())
    message += tr(" and %n generated map(s) beside it", nullptr, int(saved->writtenMaps.size()));
  Q_EMIT statusMessage(message, 6000);
  return true;
}

bool DocumentFiles::revert() {
  const QString path = m_document->filePath();
  if (path.isEmpty() || !m_document->isModified())
    return false;
  const auto answer = QMessageBox::question(
      m_parent, tr("Revert"),
      tr("Discard your changes and reload %1 as it was saved?").arg(QFileInfo(path).fileName()),
      QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel);
  if (answer != QMessageBox::Discard)
    return false;
  return openFile(path);  // already confirmed: no second prompt
}

void DocumentFiles::attachRecentMenu(QMenu* menu) {
  connect(menu, &QMenu::aboutToShow, this, [this, menu] {
    menu->clear();
    const QStringList files = settings::recentFiles();
    for (int i = 0; i < files.size(); ++i) {
      const QString& path = files[i];
      QAction* action = menu->addAction(QStringLiteral("&%1 %2").arg(
          i + 1 < 10 ? QString::number(i + 1) : QStringLiteral("0"), QFileInfo(path).fileName()));
      action->setToolTip(path);
      action->setStatusTip(path);
      connect(action, &QAction::triggered, this, [this, path] { open(path); });
    }
    if (files.isEmpty())
      menu->addAction(tr("(no recent presets)"))->setEnabled(false);
  });
}

void DocumentFiles::offerRecovery() {
  std::vector<RecoverableWork> abandoned = RecoveryStore::abandonedWork();
  if (abandoned.empty())
    return;
  const RecoverableWork& work = abandoned.front();
  QMessageBox box(QMessageBox::Question, tr("Recover unsaved work?"),
                  tr("Relief did not close properly last time. Unsaved changes to “%1” were "
                     "autosaved at %2.")
                      .arg(work.originalPath.isEmpty() ? tr("an untitled material")
                                                       : QFileInfo(work.originalPath).fileName(),
                           QLocale().toString(work.savedAt, QLocale::ShortFormat)),
                  QMessageBox::NoButton, m_parent);
  box.setObjectName(QStringLiteral("recoveryPrompt"));
  QPushButton* recover = box.addButton(tr("Recover"), QMessageBox::AcceptRole);
  box.addButton(tr("Discard"), QMessageBox::DestructiveRole);
  QPushButton* later = box.addButton(tr("Decide later"), QMessageBox::RejectRole);
  box.setDefaultButton(recover);
  box.exec();
  if (box.clickedButton() == later)
    return;
  if (box.clickedButton() != recover) {
    RecoveryStore::discard(work);
    return;
  }
  core::Result<core::LoadedPreset> loaded = core::loadPreset(work.presetPath.toStdString());
  if (!loaded) {
    QMessageBox::warning(m_parent, tr("Cannot recover"),
                         tr("%1\n\nThe autosave is kept in %2.")
                             .arg(QString::fromStdString(loaded.error()), work.folder));
    return;
  }
  core::Preset preset = std::move(loaded->preset);
  preset.preserved.remove(RecoveryStore::recoveryKey());
  // Generated maps were written into the recovery folder, which goes: they are again maps
  // without a file, written beside the preset at the next save.
  for (core::MapSlot slot : core::kAllMapSlots) {
    const core::MaterialMap& map = preset.material.map(slot);
    if (map.image && QString::fromStdString(map.sourcePath).startsWith(work.folder))
      preset.material.setMap(slot, map.image, std::string());
  }
  const core::ViewState view = preset.view;
  m_document->reset(std::move(preset), work.originalPath);
  showView(view);
  // Recovered work is unsaved work: mark it so, undoable back to nothing.
  m_document->undoStack()->resetClean();
  RecoveryStore::discard(work);
  Q_EMIT statusMessage(tr("Recovered the autosaved work; save it to keep it"), 10000);
}

void DocumentFiles::showView(const core::ViewState& view) {
  QApplication::setOverrideCursor(Qt::WaitCursor);
  const core::Status shown = m_view->showViewState(view);
  QApplication::restoreOverrideCursor();
  if (!shown)
    QMessageBox::warning(m_parent, tr("Cannot open mesh"), QString::fromStdString(shown.error()));
}

}  // namespace relief::ui::inline document
