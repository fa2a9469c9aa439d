// MainWindow; see MainWindow.h.
#include "ui/MainWindow.h"

#include "core/ImageIO.h"
#include "core/MaterialPreset.h"
#include "core/MeshImport.h"
#include "core/MeshPrimitives.h"
#include "core/export/PackageExport.h"
#include "renderer/OffscreenRenderer.h"
#include "ui/AppSettings.h"
#include "ui/CompressPanel.h"
#include "ui/DocumentFiles.h"
#include "ui/ExportDialog.h"
#include "ui/GeneratePanel.h"
#include "ui/LightPanel.h"
#include "ui/MapsPanel.h"
#include "ui/MaterialDocument.h"
#include "ui/ParameterPanel.h"
#include "ui/PreferencesDialog.h"
#include "ui/PresetLibrary.h"
#include "ui/QtText.h"
#include "ui/ShortcutsDialog.h"
#include "ui/ViewportWidget.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QScrollArea>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoView>

namespace relief::ui {
namespace {

const QStringList& imageSuffixes() {
  static const QStringList suffixes = {
      QStringLiteral("png"), QStringLiteral("jpg"),  QStringLiteral("jpeg"), QStringLiteral("tga"),
      QStringLiteral("tif"), QStringLiteral("tiff"), QStringLiteral("exr")};
  return suffixes;
}

QString imageFilter() {
  QStringList patterns;
  for (const QString& suffix : imageSuffixes())
    patterns << QStringLiteral("*.") + suffix;
  return QObject::tr("Images (%1);;All files (*)").arg(patterns.join(QLatin1Char(' ')));
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_document(new MaterialDocument(this)),
      m_viewport(new ViewportWidget(m_document)),
      m_progress(new QProgressBar),
      m_frameTime(new QLabel),
      m_rendererLabel(new QLabel) {
  setWindowTitle(tr("Relief"));
  setAcceptDrops(true);
  setCentralWidget(m_viewport);
  setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
  m_files = new DocumentFiles(
      m_document, this,
      {[this] { return currentView(); }, [this](const core::PresetView& view) { applyView(view); },
       [this] { applyDefaultView(); }});
  connect(
      m_files, &DocumentFiles::statusMessage, this,
      [this](const QString& message, int timeout) { statusBar()->showMessage(message, timeout); });
  createDocks();
  createToolBar();
  createMenus();

  m_progress->setMaximumWidth(220);
  m_progress->setVisible(false);
  statusBar()->addPermanentWidget(m_progress);
  connect(m_viewport, &ViewportWidget::errorViewProgress, this, [this](int done, int total) {
    m_progress->setVisible(total > 0);
    m_progress->setRange(0, std::max(total, 1));
    m_progress->setValue(done);
  });
  connect(m_viewport, &ViewportWidget::errorViewFinished, this,
          [this](double mean, double p95, double maximum) {
            statusBar()->showMessage(
                tr("UV error against the exact trace: mean %1, 95th percentile %2, max %3 texels")
                    .arg(mean, 0, 'f', 3)
                    .arg(p95, 0, 'f', 3)
                    .arg(maximum, 0, 'f', 2),
                15000);
          });

  m_frameTime->setToolTip(tr("CPU time of the last frame, including waiting for the GPU"));
  m_frameTime->setMinimumWidth(110);
  m_compressedLabel = new QLabel(this);
  m_compressedLabel->setToolTip(
      tr("Compressed maps are uploaded as blocks (glCompressedTexImage2D) when the driver has "
         "the format, otherwise decoded by Relief"));
  m_compressedLabel->hide();
  statusBar()->addPermanentWidget(m_compressedLabel);
  connect(m_viewport, &ViewportWidget::compressedUploadChanged, this, [this](const QString& text) {
    m_compressedLabel->setText(text);
    m_compressedLabel->setVisible(!text.isEmpty());
  });
  statusBar()->addPermanentWidget(m_rendererLabel);
  statusBar()->addPermanentWidget(m_frameTime);
  connect(m_viewport, &ViewportWidget::frameRendered, this, &MainWindow::showFrameTime);
  connect(m_viewport, &ViewportWidget::rendererReady, this,
          [this](const QString& description) { m_rendererLabel->setText(description); });
  connect(m_viewport, &ViewportWidget::renderError, this, [this](const QString& message) {
    QMessageBox::critical(this, tr("Relief: the viewport cannot render"), message);
  });
  connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
  connect(m_document, &MaterialDocument::materialReset, this, &MainWindow::updateTitle);
  connect(m_document, &MaterialDocument::fileSaved, this, &MainWindow::updateTitle);
  m_viewport->setLight(settings::viewportLight());
  m_viewport->setNativeCompressedUploads(settings::nativeCompressedUploads());
  resize(1400, 860);
  restoreWindowState();
  updateTitle();
}

MainWindow::~MainWindow() {
  // Children are deleted after this destructor has run; the document (deleted first) would
  // otherwise notify slots of this half-destroyed window.
  disconnect(m_document, nullptr, this, nullptr);
  disconnect(m_document->undoStack(), nullptr, this, nullptr);
  disconnect(m_viewport, nullptr, this, nullptr);
}

void MainWindow::createDocks() {
  auto addDock = [this](const QString& title, const QString& name, QWidget* content,
                        Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    auto* scroll = new QScrollArea;
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    dock->setWidget(scroll);
    addDockWidget(area, dock);
    return dock;
  };
  m_maps = new MapsPanel(m_document);
  m_parameters = new ParameterPanel(m_document);
  addDock(tr("Maps"), QStringLiteral("mapsDock"), m_maps, Qt::LeftDockWidgetArea);
  QDockWidget* parametersDock = addDock(tr("Parameters"), QStringLiteral("parametersDock"),
                                        m_parameters, Qt::RightDockWidgetArea);
  m_light = new LightPanel(m_viewport);
  QDockWidget* lightDock =
      addDock(tr("Light"), QStringLiteral("lightDock"), m_light, Qt::LeftDockWidgetArea);
  m_generate = new GeneratePanel(m_document);
  QDockWidget* generateDock =
      addDock(tr("Generate"), QStringLiteral("generateDock"), m_generate, Qt::RightDockWidgetArea);
  m_compressPanel = new CompressPanel(m_document, m_viewport);
  QDockWidget* compressDock = addDock(tr("Compress"), QStringLiteral("compressDock"),
                                      m_compressPanel, Qt::RightDockWidgetArea);
  connect(m_compressPanel, &CompressPanel::statusMessage, this,
          [this](const QString& message) { statusBar()->showMessage(message, 8000); });
  auto* history = new QUndoView(m_document->undoStack());
  history->setEmptyLabel(tr("<opened>"));
  QDockWidget* historyDock =
      addDock(tr("History"), QStringLiteral("historyDock"), history, Qt::RightDockWidgetArea);
  m_library = new PresetLibrary(m_document);
  QDockWidget* libraryDock =
      addDock(tr("Presets"), QStringLiteral("presetsDock"), m_library, Qt::LeftDockWidgetArea);
  connect(m_library, &PresetLibrary::openRequested, this, &MainWindow::openPreset);
  connect(m_library, &PresetLibrary::saveCurrentRequested, this, &MainWindow::saveToLibrary);
  connect(
      m_library, &PresetLibrary::statusMessage, this,
      [this](const QString& message, int timeout) { statusBar()->showMessage(message, timeout); });
  tabifyDockWidget(lightDock, libraryDock);
  lightDock->raise();
  tabifyDockWidget(parametersDock, historyDock);
  tabifyDockWidget(parametersDock, generateDock);
  tabifyDockWidget(parametersDock, compressDock);
  parametersDock->raise();
  resizeDocks({parametersDock, lightDock}, {380, 330}, Qt::Horizontal);
  connect(m_maps, &MapsPanel::loadRequested, this,
          [this](core::MapSlot slot) { chooseMapFile(slot); });
}

void MainWindow::createToolBar() {
  QToolBar* toolBar = addToolBar(tr("View"));
  toolBar->setObjectName(QStringLiteral("viewToolBar"));
  toolBar->setMovable(false);

  m_debugView = new QComboBox;
  m_debugView->setObjectName(QStringLiteral("debugView"));
  for (core::DebugView view : core::allDebugViews()) {
    m_debugView->addItem(toQString(core::debugViewLabel(view)),
                         toQString(core::debugViewName(view)));
  }
  m_debugView->setToolTip(
      tr("What the viewport shows: the shaded material or a diagnostic view "
         "(the CLI's --view). \"Samples per pixel\" is the cost; \"UV "
         "error\" compares every pixel with the exact intersection."));
  connect(m_debugView, &QComboBox::activated, this, [this](int index) {
    m_viewport->setDebugView(core::allDebugViews()[std::size_t(index)]);
  });
  toolBar->addWidget(new QLabel(tr(" View ")));
  toolBar->addWidget(m_debugView);

  m_meshBox = new QComboBox;
  m_meshBox->setObjectName(QStringLiteral("mesh"));
  for (core::PrimitiveShape shape : core::allPrimitiveShapes()) {
    const QString name = toQString(core::primitiveShapeName(shape));
    m_meshBox->addItem(name.left(1).toUpper() + name.mid(1));
  }
  m_meshBox->setToolTip(tr("The mesh the material is shown on (File > Open Mesh… for your own)."));
  connect(m_meshBox, &QComboBox::activated, this, [this](int index) {
    if (index < int(core::allPrimitiveShapes().size())) {
      showMesh(toQString(core::primitiveShapeName(core::allPrimitiveShapes()[std::size_t(index)])));
    }
  });
  toolBar->addWidget(new QLabel(tr("  Mesh ")));
  toolBar->addWidget(m_meshBox);
  toolBar->addSeparator();

  m_compare = toolBar->addAction(tr("Compare A|B"));
  m_compare->setObjectName(QStringLiteral("compare"));
  m_compare->setCheckable(true);
  m_compare->setShortcut(QKeySequence(tr("C")));
  m_compare->setToolTip(
      tr("Split the viewport: the live material left (A), a held copy right "
         "(B), on the same camera. Drag the divider. (C)"));
  connect(m_compare, &QAction::toggled, m_viewport, &ViewportWidget::setComparing);
  QAction* hold = m_holdAsB = toolBar->addAction(tr("Hold as B"));
  hold->setShortcut(QKeySequence(tr("Shift+C")));
  hold->setToolTip(
      tr("Copy the current material to the B side, then change A to compare "
         "(e.g. POM against parallax-limited, or 64 samples against 16). "
         "(Shift+C)"));
  connect(hold, &QAction::triggered, this, [this] {
    m_viewport->holdCurrentAsComparison();
    m_compare->setChecked(true);
  });
}

void MainWindow::createMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&New"), QKeySequence::New, m_files, &DocumentFiles::newDocument);
  file->addAction(tr("&Open Preset…"), QKeySequence::Open, m_files, &DocumentFiles::openWithPrompt);
  QMenu* recent = file->addMenu(tr("Open &Recent"));
  recent->setObjectName(QStringLiteral("recentMenu"));
  m_files->attachRecentMenu(recent);
  file->addAction(tr("&Save"), QKeySequence::Save, m_files, &DocumentFiles::save);
  file->addAction(tr("Save &As…"), QKeySequence(tr("Ctrl+Shift+S")), m_files,
                  &DocumentFiles::saveAs);
  QAction* revert = file->addAction(tr("Re&vert"), m_files, &DocumentFiles::revert);
  revert->setEnabled(false);
  const auto updateRevert = [this, revert] {
    revert->setEnabled(m_document->isModified() && !m_document->filePath().isEmpty());
  };
  connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, updateRevert);
  connect(m_document, &MaterialDocument::materialReset, this, updateRevert);
  connect(m_document, &MaterialDocument::fileSaved, this, updateRevert);
  file->addSeparator();
  file->addAction(tr("Open &Map…"), QKeySequence(tr("Ctrl+Shift+O")), this,
                  [this] { chooseMapFile(std::nullopt); });
  file->addAction(tr("Open M&esh…"), QKeySequence(tr("Ctrl+Shift+M")), this,
                  &MainWindow::chooseMesh);
  file->addSeparator();
  file->addAction(tr("&Export…"), QKeySequence(tr("Ctrl+E")), this, &MainWindow::showExportDialog);
  file->addAction(tr("Save Viewport &Image…"), QKeySequence(tr("Ctrl+Shift+E")), this,
                  &MainWindow::chooseViewportImage);
  file->addSeparator();
  file->addAction(tr("&Preferences…"), QKeySequence(tr("Ctrl+,")), this,
                  &MainWindow::showPreferences)
      ->setMenuRole(QAction::PreferencesRole);
  file->addSeparator();
  file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  edit->addAction(tr("Reset &Parameters"), m_document, &MaterialDocument::resetParameters);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  view->addAction(tr("&Frame Mesh"), QKeySequence(tr("F")), m_viewport, &ViewportWidget::frameMesh);
  QMenu* meshes = view->addMenu(tr("&Mesh"));
  int shortcut = 1;
  for (core::PrimitiveShape shape : core::allPrimitiveShapes()) {
    const QString name = toQString(core::primitiveShapeName(shape));
    QAction* action = meshes->addAction(name.left(1).toUpper() + name.mid(1));
    action->setShortcut(QKeySequence(QStringLiteral("Ctrl+%1").arg(shortcut++)));
    connect(action, &QAction::triggered, this, [this, name] { showMesh(name.toLower()); });
  }
  view->addAction(m_compare);
  view->addAction(m_holdAsB);
  view->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>())
    view->addAction(dock->toggleViewAction());

  QMenu* tools = menuBar()->addMenu(tr("&Tools"));
  QAction* compress =
      tools->addAction(tr("&Compress Maps"), QKeySequence(tr("Ctrl+Shift+K")), this, [this] {
        if (auto* dock = findChild<QDockWidget*>(QStringLiteral("compressDock"))) {
          dock->show();
          dock->raise();
        }
        m_compressPanel->compress();
      });
  compress->setToolTip(tr("Compress the maps in the formats chosen in the Compress panel"));
  tools->addAction(tr("Compare &All Formats…"), m_compressPanel, &CompressPanel::openCompareAll);
  tools->addAction(tr("Compare Compressed Map in &2D…"), m_compressPanel,
                   &CompressPanel::openCompare);
  QMenu* compressedView = tools->addMenu(tr("Viewport Shows"));
  const QString viewNames[] = {tr("&Original Maps"), tr("&Compressed Maps"),
                               tr("&Wipe: Original | Compressed")};
  for (int i = 0; i < 3; ++i) {
    QAction* action = compressedView->addAction(viewNames[i]);
    action->setShortcut(QKeySequence(QStringLiteral("Alt+%1").arg(i + 1)));
    connect(action, &QAction::triggered, this,
            [this, i] { m_compressPanel->viewBox()->setCurrentIndex(i); });
  }

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&Keyboard Shortcuts"), QKeySequence(tr("Ctrl+/")), this,
                  &MainWindow::showShortcuts);
  help->addAction(tr("Viewport &Controls"), this, &MainWindow::showControlsHelp);
  help->addAction(tr("&About Relief"), this, [this] {
    QMessageBox::about(this, tr("About Relief"),
                       tr("<b>Relief</b> %1<br>A material editor for height-map relief: "
                          "normal mapping, parallax and self-shadowing.")
                           .arg(QApplication::applicationVersion()));
  });
}

void MainWindow::showControlsHelp() {
  QMessageBox::information(this, tr("Viewport controls"), m_viewport->toolTip());
}

void MainWindow::showFrameTime(double milliseconds) {
  m_frameTime->setText(tr("frame %1 ms").arg(milliseconds, 0, 'f', 1));
}

void MainWindow::updateTitle() {
  setWindowTitle(
      QStringLiteral("%1%2 — Relief")
          .arg(m_files->displayName(), m_document->isModified() ? QStringLiteral("*") : QString()));
}

bool MainWindow::isImageFile(const QString& path) {
  return imageSuffixes().contains(QFileInfo(path).suffix().toLower());
}

bool MainWindow::isPresetFile(const QString& path) {
  return QFileInfo(path).suffix().toLower() == QStringLiteral("relief");
}

bool MainWindow::openPreset(const QString& path) {
  return m_files->open(path);
}

bool MainWindow::loadMapFile(const QString& path, std::optional<core::MapSlot> slot) {
  if (!slot)
    slot = core::guessMapSlotFromFileName(QFileInfo(path).fileName().toStdString());
  if (!slot) {
    QStringList labels;
    for (core::MapSlot candidate : core::kAllMapSlots)
      labels << toQString(core::mapSlotLabel(candidate));
    bool ok = false;
    const QString chosen = QInputDialog::getItem(
        this, tr("Which map is this?"),
        tr("%1 does not say which map it is.\nUse it as:").arg(QFileInfo(path).fileName()), labels,
        0, false, &ok);
    if (!ok)
      return false;
    slot = core::kAllMapSlots[std::size_t(labels.indexOf(chosen))];
  }
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<core::Image> image = core::loadImage(path.toStdString());
  QApplication::restoreOverrideCursor();
  if (!image) {
    QMessageBox::warning(this, tr("Cannot load map"), QString::fromStdString(image.error()));
    return false;
  }
  m_document->setMap(*slot, std::make_shared<core::Image>(std::move(image).value()),
                     QFileInfo(path).absoluteFilePath());
  settings::setLastFolder(QStringLiteral("map"), QFileInfo(path).absolutePath());
  statusBar()->showMessage(
      tr("Loaded %1 as the %2 map")
          .arg(QFileInfo(path).fileName(), toQString(core::mapSlotLabel(*slot)).toLower()),
      5000);
  return true;
}

void MainWindow::openFiles(const QStringList& paths) {
  for (const QString& path : paths) {
    if (isPresetFile(path)) {
      openPreset(path);
    } else {
      loadMapFile(path);
    }
  }
}

bool MainWindow::openMesh(const QString& path) {
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<core::ImportedMesh> imported = core::importMesh(path.toStdString());
  QApplication::restoreOverrideCursor();
  if (!imported) {
    QMessageBox::warning(this, tr("Cannot open mesh"), QString::fromStdString(imported.error()));
    return false;
  }
  const core::Mesh& mesh = imported->mesh;
  statusBar()->showMessage(
      tr("Opened %1: %2 triangles, tangents %3")
          .arg(QFileInfo(path).fileName())
          .arg(mesh.triangleCount())
          .arg(imported->tangentsFromFile ? tr("from the file") : tr("computed")),
      8000);
  const QString label = QFileInfo(path).fileName();
  const int customIndex = int(core::allPrimitiveShapes().size());
  if (m_meshBox->count() > customIndex)
    m_meshBox->removeItem(customIndex);
  m_meshBox->addItem(label);
  m_meshBox->setCurrentIndex(customIndex);
  m_viewport->setMesh(std::move(imported->mesh));
  m_meshSource = QFileInfo(path).absoluteFilePath();
  settings::setLastFolder(QStringLiteral("mesh"), QFileInfo(path).absolutePath());
  return true;
}

void MainWindow::chooseMesh() {
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Open mesh"), settings::lastFolder(QStringLiteral("mesh")),
      tr("Meshes (%1);;All files (*)").arg(QString::fromStdString(core::meshFileFilter())));
  if (!path.isEmpty())
    openMesh(path);
}

void MainWindow::chooseMapFile(std::optional<core::MapSlot> slot) {
  const QString title =
      slot ? tr("Load %1 map").arg(toQString(core::mapSlotLabel(*slot)).toLower()) : tr("Open map");
  const QString path = QFileDialog::getOpenFileName(
      this, title, settings::lastFolder(QStringLiteral("map")), imageFilter());
  if (!path.isEmpty())
    loadMapFile(path, slot);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  for (const QUrl& url : event->mimeData()->urls()) {
    const QString path = url.toLocalFile();
    if (isImageFile(path) || isPresetFile(path)) {
      event->acceptProposedAction();
      return;
    }
  }
}

void MainWindow::dropEvent(QDropEvent* event) {
  QStringList paths;
  for (const QUrl& url : event->mimeData()->urls()) {
    const QString path = url.toLocalFile();
    if (isImageFile(path) || isPresetFile(path))
      paths << path;
  }
  event->acceptProposedAction();
  openFiles(paths);
}

bool MainWindow::showMesh(const QString& nameOrPath) {
  if (const auto shape = core::findPrimitiveShape(nameOrPath.toStdString())) {
    m_meshBox->setCurrentIndex(int(*shape));
    m_viewport->setMesh(core::makePrimitive(*shape));
    m_meshSource = nameOrPath;
    return true;
  }
  return openMesh(nameOrPath);
}

core::PresetView MainWindow::currentView() const {
  core::PresetView view;
  view.camera = m_viewport->view().camera;
  view.light = m_viewport->view().light;
  view.mesh = m_meshSource.toStdString();
  return view;
}

void MainWindow::applyView(const core::PresetView& view) {
  // What the preset does not say stays as it is (the samples store no view).
  if (!view.mesh.empty() && QString::fromStdString(view.mesh) != m_meshSource)
    showMesh(QString::fromStdString(view.mesh));
  if (view.camera)
    m_viewport->setCamera(*view.camera);
  else
    m_viewport->frameMesh();
  if (view.light)
    m_viewport->setLight(*view.light);
}

void MainWindow::applyDefaultView() {
  showMesh(settings::defaultMesh());
}

void MainWindow::setBundledPresetFolder(const QString& folder) {
  m_files->setProtectedFolder(folder);
  m_library->setBundledFolder(folder);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!m_files->maybeSave(tr("closing"))) {
    event->ignore();
    return;
  }
  saveWindowState();
  event->accept();
}

void MainWindow::restoreWindowState() {
  const QSettings settings;
  restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
  restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
}

void MainWindow::saveWindowState() {
  QSettings settings;
  settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
  settings.setValue(QStringLiteral("window/state"), saveState());
  settings::setViewportLight(m_viewport->view().light);
}

void MainWindow::showShortcuts() {
  ShortcutsDialog dialog(menuBar(), m_viewport->toolTip(), this);
  dialog.exec();
}

void MainWindow::showPreferences() {
  PreferencesDialog dialog(this);
  if (dialog.exec() == QDialog::Accepted) {
    m_files->updateAutosaveInterval();
    m_viewport->setNativeCompressedUploads(settings::nativeCompressedUploads());
  }
}

void MainWindow::showExportDialog() {
  ExportDialog dialog(m_document->toPreset(currentView()), m_viewport->mesh(), this);
  dialog.exec();
}

void MainWindow::saveToLibrary() {
  bool ok = false;
  const QString suggested = QString::fromStdString(core::exportStem(m_document->material()));
  const QString name = QInputDialog::getText(this, tr("Save as preset"), tr("Preset name:"),
                                             QLineEdit::Normal, suggested, &ok)
                           .trimmed();
  if (!ok || name.isEmpty())
    return;
  core::Preset preset = m_document->toPreset(currentView());
  preset.material.setName(name.toStdString());
  const QString folder = PresetLibrary::userFolder() + QLatin1Char('/') +
                         QString::fromStdString(core::exportStem(preset.material));
  if (QFileInfo::exists(folder) &&
      QMessageBox::question(this, tr("Save as preset"),
                            tr("You already have a preset called “%1”. Replace it?").arg(name),
                            QMessageBox::Yes | QMessageBox::Cancel,
                            QMessageBox::Cancel) != QMessageBox::Yes) {
    return;
  }
  // A package: the library keeps its own copies of the maps (16-bit), so it does not break
  // when the originals move.
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<std::string> saved = core::exportPackage(preset, folder.toStdString());
  QApplication::restoreOverrideCursor();
  if (!saved) {
    QMessageBox::critical(this, tr("Cannot save preset"), QString::fromStdString(saved.error()));
    return;
  }
  m_library->refresh();
  statusBar()->showMessage(tr("Added “%1” to your presets").arg(name), 5000);
}

bool MainWindow::saveViewportImage(const QString& path, int width, int height) {
  QApplication::setOverrideCursor(Qt::WaitCursor);
  core::Result<core::Image> image = [&]() -> core::Result<core::Image> {
    auto offscreen = renderer::OffscreenRenderer::create();
    if (!offscreen)
      return core::makeError(offscreen.error());
    if (width > offscreen.value()->maxSize() || height > offscreen.value()->maxSize()) {
      return core::makeError(QStringLiteral("%1x%2 is larger than this GPU renders (%3)")
                                 .arg(width)
                                 .arg(height)
                                 .arg(offscreen.value()->maxSize())
                                 .toStdString());
    }
    offscreen.value()->setMesh(m_viewport->mesh());
    const auto [material, frame] = m_viewport->shownFrame();
    offscreen.value()->setMaterial(material);
    return offscreen.value()->render(frame, width, height);
  }();
  core::Status saved =
      image ? core::saveImage(image.value(), path.toStdString(), core::SampleFormat::UInt8)
            : core::Status(core::makeError(image.error()));
  QApplication::restoreOverrideCursor();
  if (!saved) {
    QMessageBox::critical(this, tr("Cannot save the viewport image"),
                          tr("%1: %2").arg(path, QString::fromStdString(saved.error())));
    return false;
  }
  statusBar()->showMessage(
      tr("Saved %1 (%2x%3)").arg(QFileInfo(path).fileName()).arg(width).arg(height), 6000);
  return true;
}

void MainWindow::chooseViewportImage() {
  QDialog sizeDialog(this);
  sizeDialog.setWindowTitle(tr("Save viewport image"));
  auto* widthBox = new QSpinBox;
  auto* heightBox = new QSpinBox;
  for (QSpinBox* box : {widthBox, heightBox}) {
    box->setRange(16, core::kMaxImageDimension);
    box->setSuffix(tr(" px"));
  }
  // Twice the viewport by default: a sharper picture of exactly what is on screen.
  const qreal scale = 2.0 * devicePixelRatioF();
  widthBox->setValue(int(m_viewport->width() * scale));
  heightBox->setValue(int(m_viewport->height() * scale));
  auto* form = new QFormLayout(&sizeDialog);
  form->addRow(tr("Width"), widthBox);
  form->addRow(tr("Height"), heightBox);
  form->addRow(new QLabel(tr("Rendered offscreen with the viewport's camera, light and view.")));
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, &sizeDialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &sizeDialog, &QDialog::reject);
  form->addRow(buttons);
  if (sizeDialog.exec() != QDialog::Accepted)
    return;
  const QString suggested =
      settings::lastFolder(QStringLiteral("image"), false) + QLatin1Char('/') +
      m_files->displayName().section(QLatin1Char('.'), 0, 0) + QStringLiteral(".png");
  const QString path = QFileDialog::getSaveFileName(this, tr("Save viewport image"), suggested,
                                                    tr("Images (*.png *.jpg *.tif)"));
  if (path.isEmpty())
    return;
  if (saveViewportImage(path, widthBox->value(), heightBox->value()))
    settings::setLastFolder(QStringLiteral("image"), QFileInfo(path).absolutePath());
}

}  // namespace relief::ui
