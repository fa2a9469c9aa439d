// PresetLibrary; see PresetLibrary.h.
#include "ui/document/PresetLibrary.h"

#include "core/exporters/PackageExport.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "renderer/ImageConversion.h"
#include "renderer/OffscreenRenderer.h"
#include "ui/document/MaterialDocument.h"
#include "ui/tasks/BackgroundTask.h"

#include <QApplication>
#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>
#include <QVBoxLayout>

namespace relief::ui::inline document {
namespace {

constexpr int kPathRole = Qt::UserRole;
constexpr int kUserRole = Qt::UserRole + 1;

QIcon placeholderIcon() {
  QPixmap pixmap(PresetLibrary::kThumbnailSize, PresetLibrary::kThumbnailSize);
  pixmap.fill(QColor(60, 60, 64));
  return QIcon(pixmap);
}

}  // namespace

PresetLibrary::PresetLibrary(MaterialDocument* document, QWidget* parent)
    : QWidget(parent),
      m_document(document),
      m_saving(new BackgroundTask(this)),
      m_loading(new BackgroundTask(this)),
      m_list(new QListWidget),
      m_open(new QPushButton(tr("Open"))),
      m_apply(new QPushButton(tr("Apply"))),
      m_delete(new QPushButton(tr("Delete"))) {
  m_list->setObjectName(QStringLiteral("presetList"));
  m_list->setViewMode(QListView::IconMode);
  m_list->setIconSize(QSize(kThumbnailSize, kThumbnailSize));
  m_list->setResizeMode(QListView::Adjust);
  m_list->setMovement(QListView::Static);
  m_list->setSpacing(6);
  m_list->setWordWrap(true);
  m_list->setUniformItemSizes(true);
  m_list->setMinimumHeight(kThumbnailSize + 40);

  m_open->setToolTip(
      tr("Open the preset whole: maps, technique, parameters and view "
         "(double-click does the same)."));
  m_apply->setToolTip(
      tr("Take the preset's technique and parameters onto the current maps, "
         "as one step you can undo."));
  m_delete->setToolTip(tr("Delete one of your presets (bundled ones stay)."));
  auto* saveCurrent = new QPushButton(tr("Save Current as Preset…"));
  saveCurrent->setToolTip(
      tr("Add the current material to your presets, with copies of its "
         "maps."));

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_open);
  buttons->addWidget(m_apply);
  buttons->addWidget(m_delete);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_list);
  layout->addLayout(buttons);
  layout->addWidget(saveCurrent);

  connect(m_list, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
    Q_EMIT openRequested(item->data(kPathRole).toString());
  });
  connect(m_list, &QListWidget::itemSelectionChanged, this, &PresetLibrary::updateButtons);
  connect(m_open, &QPushButton::clicked, this, [this] {
    if (!selectedPath().isEmpty())
      Q_EMIT openRequested(selectedPath());
  });
  connect(m_apply, &QPushButton::clicked, this, [this] { applyParameters(selectedPath()); });
  connect(m_delete, &QPushButton::clicked, this, [this] { deletePreset(selectedPath()); });
  connect(saveCurrent, &QPushButton::clicked, this, &PresetLibrary::saveCurrentRequested);
  updateButtons();
  refresh();
}

PresetLibrary::~PresetLibrary() {
  m_pendingThumbnails.clear();
  m_loading->cancel();
  m_loading->waitForFinished();
}

QString PresetLibrary::userFolder() {
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
         QStringLiteral("/presets");
}

void PresetLibrary::setBundledFolder(const QString& folder) {
  m_bundledFolder = folder;
  refresh();
}

void PresetLibrary::refresh() {
  m_list->clear();
  m_pendingThumbnails.clear();
  if (!m_bundledFolder.isEmpty())
    addPresets(m_bundledFolder, false);
  addPresets(userFolder(), true);
  loadNextThumbnail();
  updateButtons();
}

void PresetLibrary::addPresets(const QString& folder, bool user) {
  QStringList paths;
  QDirIterator it(folder, {QStringLiteral("*.relief")}, QDir::Files, QDirIterator::Subdirectories);
  while (it.hasNext())
    paths << it.next();
  paths.sort();
  for (const QString& path : paths) {
    auto* item = new QListWidgetItem(QFileInfo(path).completeBaseName(), m_list);
    item->setData(kPathRole, path);
    item->setData(kUserRole, user);
    item->setToolTip(user ? tr("%1 (yours)").arg(path) : tr("%1 (bundled)").arg(path));
    const QIcon cached = cachedThumbnail(path);
    item->setIcon(cached.isNull() ? placeholderIcon() : cached);
    if (cached.isNull())
      m_pendingThumbnails << path;
  }
}

QString PresetLibrary::thumbnailCachePath(const QString& path) const {
  // Keyed by the preset's path and modification time, so an edited preset is drawn again.
  const QFileInfo info(path);
  const QByteArray key = (info.absoluteFilePath() + QLatin1Char('|') +
                          QString::number(info.lastModified().toMSecsSinceEpoch()) +
                          QLatin1Char('|') + QString::number(kThumbnailSize))
                             .toUtf8();
  return QStandardPaths::writableLocation(QStandardPaths::CacheLocation) +
         QStringLiteral("/thumbnails/") +
         QString::fromLatin1(QCryptographicHash::hash(key, QCryptographicHash::Sha1).toHex()) +
         QStringLiteral(".png");
}

QIcon PresetLibrary::cachedThumbnail(const QString& path) const {
  const QString cache = thumbnailCachePath(path);
  return QFileInfo::exists(cache) ? QIcon(cache) : QIcon();
}

// One preset at a time: its maps load in the background, then the renderer draws it here (GL
// contexts belong to this thread), then the next one starts.
void PresetLibrary::loadNextThumbnail() {
  if (m_pendingThumbnails.isEmpty() || m_loading->isRunning())
    return;
  const QString next = m_pendingThumbnails.takeFirst();
  using Loaded = core::Result<core::LoadedPreset>;
  m_loading->run<Loaded>(
      [next](const core::WorkControl&) { return core::loadPreset(next.toStdString()); },
      [this, next](Loaded&& loaded) {
        if (loaded)
          renderThumbnail(next, loaded->preset.material);
        loadNextThumbnail();
      });
}

void PresetLibrary::renderThumbnail(const QString& source, const core::Material& material) {
  if (m_rendererFailed)
    return;
  if (!m_renderer) {
    auto created = renderer::OffscreenRenderer::create();
    if (!created) {
      m_rendererFailed = true;
      Q_EMIT statusMessage(tr("Preset thumbnails: %1").arg(QString::fromStdString(created.error())),
                           10000);
      return;
    }
    m_renderer = std::move(created).value();
    m_renderer->setMesh(core::makeSphere());
  }
  renderer::RenderView view;
  view.camera = core::defaultCameraFor(core::makeSphere(), 1.0f);
  view.camera.yawDeg = 20.0f;
  view.camera.pitchDeg = 25.0f;
  m_renderer->setMaterial(material);
  // Supersampled, then box-filtered down: smooth edges at thumbnail size.
  core::Result<core::Image> image =
      m_renderer->render(view, kThumbnailSize * 2, kThumbnailSize * 2);
  if (!image)
    return;
  const QImage thumbnail = renderer::makeThumbnail(image.value(), kThumbnailSize);
  const QString cache = thumbnailCachePath(source);
  QDir().mkpath(QFileInfo(cache).absolutePath());
  thumbnail.save(cache);
  for (int i = 0; i < m_list->count(); ++i) {
    if (m_list->item(i)->data(kPathRole).toString() == source)
      m_list->item(i)->setIcon(QIcon(QPixmap::fromImage(thumbnail)));
  }
}

QString PresetLibrary::selectedPath() const {
  const QList<QListWidgetItem*> selected = m_list->selectedItems();
  return selected.isEmpty() ? QString() : selected.front()->data(kPathRole).toString();
}

void PresetLibrary::updateButtons() {
  const QList<QListWidgetItem*> selected = m_list->selectedItems();
  m_open->setEnabled(!selected.isEmpty());
  m_apply->setEnabled(!selected.isEmpty());
  m_delete->setEnabled(!selected.isEmpty() && selected.front()->data(kUserRole).toBool());
}

bool PresetLibrary::applyParameters(const QString& path) {
  if (path.isEmpty())
    return false;
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<core::LoadedPreset> loaded = core::loadPreset(path.toStdString());
  QApplication::restoreOverrideCursor();
  if (!loaded) {
    QMessageBox::warning(this, tr("Cannot apply preset"), QString::fromStdString(loaded.error()));
    return false;
  }
  m_document->applyLook(loaded->preset.material,
                        tr("Apply preset %1").arg(QFileInfo(path).completeBaseName()));
  Q_EMIT statusMessage(tr("Applied the technique and parameters of %1 (Ctrl+Z undoes)")
                           .arg(QFileInfo(path).completeBaseName()),
                       6000);
  return true;
}

bool PresetLibrary::deletePreset(const QString& path) {
  const QString folder = QFileInfo(path).absolutePath();
  if (path.isEmpty() || !folder.startsWith(QDir(userFolder()).absolutePath()))
    return false;
  const auto answer = QMessageBox::question(
      this, tr("Delete preset"),
      tr("Delete your preset “%1” and its maps?").arg(QFileInfo(path).completeBaseName()),
      QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
  if (answer != QMessageBox::Yes)
    return false;
  // Presets saved here live in a folder of their own (the preset and its map copies).
  if (QDir(folder) != QDir(userFolder()))
    QDir(folder).removeRecursively();
  else
    QFile::remove(path);
  refresh();
  return true;
}

bool PresetLibrary::isSaving() const {
  return m_saving->isRunning();
}

void PresetLibrary::saveCurrent(core::Preset preset) {
  bool ok = false;
  const QString suggested = QString::fromStdString(core::exportStem(preset.material));
  const QString name = QInputDialog::getText(this, tr("Save as preset"), tr("Preset name:"),
                                             QLineEdit::Normal, suggested, &ok)
                           .trimmed();
  if (!ok || name.isEmpty())
    return;
  preset.material.setName(name.toStdString());
  const QString folder =
      userFolder() + QLatin1Char('/') + QString::fromStdString(core::exportStem(preset.material));
  if (QFileInfo::exists(folder) &&
      QMessageBox::question(this, tr("Save as preset"),
                            tr("You already have a preset called “%1”. Replace it?").arg(name),
                            QMessageBox::Yes | QMessageBox::Cancel,
                            QMessageBox::Cancel) != QMessageBox::Yes) {
    return;
  }
  Q_EMIT statusMessage(tr("Saving “%1” to your presets…").arg(name), 0);
  using Saved = core::Result<std::string>;
  m_saving->run<Saved>(
      [preset = std::move(preset), folder = folder.toStdString()](const core::WorkControl&) {
        return core::exportPackage(preset, folder);
      },
      [this, name](Saved&& saved) {
        if (!saved) {
          QMessageBox::critical(this, tr("Cannot save preset"),
                                QString::fromStdString(saved.error()));
          return;
        }
        refresh();
        Q_EMIT statusMessage(tr("Added “%1” to your presets").arg(name), 5000);
      });
}

}  // namespace relief::ui::inline document
