// MainWindow; see MainWindow.h.
#include "ui/window/MainWindow.h"

#include "core/mesh/MeshImport.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "ui/QtText.h"
#include "ui/dialogs/ExportDialog.h"
#include "ui/dialogs/PreferencesDialog.h"
#include "ui/dialogs/ShortcutsDialog.h"
#include "ui/document/DocumentFiles.h"
#include "ui/document/MaterialDocument.h"
#include "ui/document/PresetLibrary.h"
#include "ui/document/ViewDocument.h"
#include "ui/panels/CompressPanel.h"
#include "ui/panels/GeneratePanel.h"
#include "ui/panels/LightPanel.h"
#include "ui/panels/MapsPanel.h"
#include "ui/panels/ParameterPanel.h"
#include "ui/settings/AppSettings.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/CostTableWindow.h"
#include "ui/window/MapFileLoader.h"
#include "ui/window/ViewToolBar.h"
#include "ui/window/ViewportImageExport.h"
#include "ui/window/ViewportStatus.h"

#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QUndoView>

#include <cmath>

namespace relief::ui::inline window {
MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_document(new MaterialDocument(this)),
      m_view(new ViewDocument(m_document->undoStack(), this)),
      m_viewport(new ViewportWidget(m_document, m_view)) {
  setWindowTitle(tr("Relief"));
  setAcceptDrops(true);
  setCentralWidget(m_viewport);
  setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
  m_files = new DocumentFiles(m_document, m_view, this);
  m_mapLoader = new MapFileLoader(m_document, this);
  m_imageExport = new ViewportImageExport(m_view, m_viewport, this);
  const auto showStatus = [this](const QString& message, int timeout) {
    statusBar()->showMessage(message, timeout);
  };
  connect(m_files, &DocumentFiles::statusMessage, this, showStatus);
  connect(m_mapLoader, &MapFileLoader::statusMessage, this, showStatus);
  connect(m_imageExport, &ViewportImageExport::statusMessage, this, showStatus);
  createDocks();
  m_toolBar = new ViewToolBar(m_view, m_viewport, this);
  addToolBar(m_toolBar);
  connect(m_toolBar, &ViewToolBar::meshRequested, this, &MainWindow::showMesh);
  createMenus();

  m_status = new ViewportStatus(m_viewport, m_document, statusBar());
  connect(m_viewport, &ViewportWidget::renderError, this, [this](const QString& message) {
    QMessageBox::critical(this, tr("Relief: the viewport cannot render"), message);
  });
  connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
  connect(m_document, &MaterialDocument::materialReset, this, &MainWindow::updateTitle);
  connect(m_document, &MaterialDocument::fileSaved, this, &MainWindow::updateTitle);
  // The last session's light and look, not as undo steps: a new window has no history.
  m_view->applyLight(settings::viewportLight());
  m_view->applyDisplay(settings::viewportDisplay());
  m_view->applyEnvironment(settings::viewportEnvironment());
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
  m_light = new LightPanel(m_view);
  QDockWidget* lightDock =
      addDock(tr("Light"), QStringLiteral("lightDock"), m_light, Qt::LeftDockWidgetArea);
  m_generate = new GeneratePanel(m_document);
  QDockWidget* generateDock =
      addDock(tr("Generate"), QStringLiteral("generateDock"), m_generate, Qt::RightDockWidgetArea);
  m_compressPanel = new CompressPanel(m_document, m_view);
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
  connect(m_library, &PresetLibrary::saveCurrentRequested, this,
          [this] { m_library->saveCurrent(m_document->toPreset(m_view->viewState())); });
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
  connect(m_maps, &MapsPanel::loadRequested, m_mapLoader,
          [this](core::MapSlot slot) { m_mapLoader->choose(slot); });
  connect(m_maps, &MapsPanel::loadOrmRequested, m_mapLoader, &MapFileLoader::chooseOrm);
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
                  [this] { m_mapLoader->choose(std::nullopt); });
  file->addAction(tr("Open M&esh…"), QKeySequence(tr("Ctrl+Shift+M")), this,
                  &MainWindow::chooseMesh);
  file->addSeparator();
  file->addAction(tr("&Export…"), QKeySequence(tr("Ctrl+E")), this, &MainWindow::showExportDialog);
  file->addAction(tr("Save Viewport &Image…"), QKeySequence(tr("Ctrl+Shift+E")), this,
                  [this] { m_imageExport->choose(m_files->displayName()); });
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
  view->addAction(tr("&Frame Mesh"), QKeySequence(tr("F")), m_view, &ViewDocument::requestFraming);
  QMenu* meshes = view->addMenu(tr("&Mesh"));
  int shortcut = 1;
  for (core::PrimitiveShape shape : core::allPrimitiveShapes()) {
    const QString name = toQString(core::primitiveShapeName(shape));
    QAction* action = meshes->addAction(name.left(1).toUpper() + name.mid(1));
    action->setShortcut(QKeySequence(QStringLiteral("Ctrl+%1").arg(shortcut++)));
    connect(action, &QAction::triggered, this, [this, name] { showMesh(name.toLower()); });
  }
  view->addAction(m_toolBar->compareAction());
  view->addAction(m_toolBar->holdAction());
  view->addAction(m_toolBar->fartherAction());
  view->addAction(m_toolBar->closerAction());
  view->addAction(m_toolBar->engineCycleAction());
  view->addAction(m_toolBar->engineGridAction());
  QAction* costTable =
      view->addAction(tr("Cost &Table…"), QKeySequence(tr("Shift+K")), this, [this] {
        if (!m_costTable)
          m_costTable = new CostTableWindow(m_document, m_view, m_viewport, this);
        m_costTable->show();
        m_costTable->raise();
        m_costTable->measure();
      });
  costTable->setObjectName(QStringLiteral("costTableAction"));
  costTable->setToolTip(
      tr("Every technique's frame time and UV error at this view, and the "
         "cheapest within the error you accept."));
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

QLabel* MainWindow::compressedUploadLabel() const {
  return m_status->compressedUploadLabel();
}

void MainWindow::updateTitle() {
  setWindowTitle(
      QStringLiteral("%1%2 — Relief")
          .arg(m_files->displayName(), m_document->isModified() ? QStringLiteral("*") : QString()));
}

bool MainWindow::isImageFile(const QString& path) {
  return MapFileLoader::isImageFile(path);
}

bool MainWindow::isPresetFile(const QString& path) {
  return QFileInfo(path).suffix().toLower() == QStringLiteral("relief");
}

QComboBox* MainWindow::debugViewBox() const {
  return m_toolBar->debugViewBox();
}

QComboBox* MainWindow::meshBox() const {
  return m_toolBar->meshBox();
}

QAction* MainWindow::compareAction() const {
  return m_toolBar->compareAction();
}

const QString& MainWindow::meshSource() const {
  return m_view->meshSource();
}

bool MainWindow::openPreset(const QString& path) {
  return m_files->open(path);
}

bool MainWindow::loadMapFile(const QString& path, std::optional<core::MapSlot> slot) {
  return m_mapLoader->load(path, slot);
}

bool MainWindow::saveViewportImage(const QString& path, int width, int height) {
  return m_imageExport->save(path, width, height);
}

void MainWindow::openFiles(const QStringList& paths) {
  QStringList maps;
  for (const QString& path : paths) {
    if (isPresetFile(path))
      openPreset(path);
    else
      maps << path;
  }
  if (!maps.isEmpty())
    m_mapLoader->loadSet(maps);
}

bool MainWindow::showMesh(const QString& nameOrPath) {
  QApplication::setOverrideCursor(Qt::WaitCursor);
  const core::Result<QString> shown = m_view->showMesh(nameOrPath);
  QApplication::restoreOverrideCursor();
  if (!shown) {
    QMessageBox::warning(this, tr("Cannot open mesh"), QString::fromStdString(shown.error()));
    return false;
  }
  if (!shown.value().isEmpty()) {
    statusBar()->showMessage(
        tr("Opened %1: %2").arg(QFileInfo(nameOrPath).fileName(), shown.value()), 8000);
    settings::setLastFolder(QStringLiteral("mesh"), QFileInfo(nameOrPath).absolutePath());
  }
  return true;
}

void MainWindow::chooseMesh() {
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Open mesh"), settings::lastFolder(QStringLiteral("mesh")),
      tr("Meshes (%1);;All files (*)").arg(QString::fromStdString(core::meshFileFilter())));
  if (!path.isEmpty())
    showMesh(path);
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
  settings::setViewportLight(m_view->light());
  settings::setViewportDisplay(m_view->display());
  settings::setViewportEnvironment(m_view->environment());
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
  ExportDialog dialog(m_document->toPreset(m_view->viewState()), m_view->mesh(), this);
  dialog.exec();
}

}  // namespace relief::ui::inline window
