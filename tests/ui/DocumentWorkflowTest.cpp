// The editing workflow through the real main window: open, change, save, reopen and get the
// same material; the prompt before unsaved changes are lost (on close, New and Revert);
// autosave and recovery after a crash; the preset library; export; viewport images; the
// shortcut list. Modal dialogs are answered by a timer, as a user would click them.
#include "core/image/ImageIO.h"
#include "core/preset/MaterialPreset.h"
#include "support/DialogAnswerer.h"
#include "support/MainWindowFixture.h"
#include "support/TestPaths.h"
#include "ui/dialogs/ExportDialog.h"
#include "ui/dialogs/ShortcutsDialog.h"
#include "ui/document/DocumentFiles.h"
#include "ui/document/MaterialDocument.h"
#include "ui/document/PresetLibrary.h"
#include "ui/document/RecoveryStore.h"
#include "ui/panels/ParameterPanel.h"
#include "ui/panels/ParameterSlider.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/MainWindow.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace relief::test {
namespace {

// A copy of a sample (preset and maps) that the test may change and overwrite.
std::string copySample(const std::string& name, const std::string& folderName) {
  const std::string folder = scratchFolder() + "/" + folderName;
  std::filesystem::remove_all(folder);
  std::filesystem::copy(sourcePath("samples/" + name), folder);
  return folder + "/" + name + ".relief";
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

class DocumentWorkflow : public MainWindowFixture {
 protected:
  void SetUp() override {
    m_path = copySample("bricks", "workflow");
    openWindow(1100, 750, m_path);
  }

  // Types a value into a parameter's spin box, as a user does.
  void typeParameter(core::ParamId id, double value) {
    auto* slider = qobject_cast<ui::ParameterSlider*>(m_window->parameterPanel()->editor(id));
    ASSERT_NE(slider, nullptr);
    slider->spinBox()->setValue(value);
  }

  std::string m_path;
};

TEST_F(DocumentWorkflow, ChangeSaveReopenGivesTheSameMaterial) {
  typeParameter(core::ParamId::HeightScale, 0.05);
  typeParameter(core::ParamId::Tiling, 3.0);
  EXPECT_TRUE(m_window->windowTitle().contains(QLatin1Char('*')));
  // Ctrl+S: the action bound to it in the menus saves.
  QAction* save = nullptr;
  for (QAction* action : m_window->findChildren<QAction*>()) {
    if (action->shortcut() == QKeySequence(QStringLiteral("Ctrl+S")))
      save = action;
  }
  ASSERT_NE(save, nullptr);
  save->trigger();
  EXPECT_FALSE(document()->isModified());
  EXPECT_FALSE(m_window->windowTitle().contains(QLatin1Char('*')));
  const core::Material saved = document()->material();

  ui::MainWindow reopened;
  reopened.show();
  ASSERT_TRUE(reopened.openPreset(QString::fromStdString(m_path)));
  const core::Material& loaded = reopened.document()->material();
  EXPECT_EQ(loaded.parameters(), saved.parameters());
  EXPECT_DOUBLE_EQ(loaded.parameter(core::ParamId::HeightScale), 0.05);
  EXPECT_EQ(loaded.technique(), saved.technique());
  for (core::MapSlot slot : core::kAllMapSlots) {
    ASSERT_EQ(loaded.hasMap(slot), saved.hasMap(slot));
    if (saved.hasMap(slot)) {
      EXPECT_TRUE(*loaded.image(slot) == *saved.image(slot)) << core::mapSlotName(slot);
    }
  }
  // The view went with it.
  EXPECT_EQ(reopened.meshSource(), m_window->meshSource());
  EXPECT_FLOAT_EQ(reopened.viewport()->view().camera.yawDeg,
                  m_window->viewport()->view().camera.yawDeg);
}

// The view's edits (light, environment, display, mesh) are the preset's: saved, and shown again
// when it is reopened.
TEST_F(DocumentWorkflow, ViewEditsAreSavedAndReopened) {
  ui::ViewDocument* view = viewDocument();
  core::DirectionalLight light = view->light();
  light.azimuthDeg = 210.0f;
  light.elevationDeg = 22.0f;
  light.intensity = 1.7f;
  view->setLight(light);
  core::Environment environment = view->environment();
  environment.source = "sky";
  environment.rotationDeg = -60.0f;
  view->setEnvironment(environment);
  core::DisplayTransform display = view->display();
  display.exposureEv = -0.5f;
  display.toneMapper = core::ToneMapper::PbrNeutral;
  view->setDisplay(display);
  ASSERT_TRUE(view->showMesh(QStringLiteral("sphere")));
  EXPECT_TRUE(document()->isModified()) << "view edits are unsaved work";
  ASSERT_TRUE(document()->save(QString::fromStdString(m_path), view->viewState()));

  ui::MainWindow reopened;
  reopened.show();
  ASSERT_TRUE(reopened.openPreset(QString::fromStdString(m_path)));
  const ui::ViewDocument* shown = reopened.viewDocument();
  EXPECT_EQ(shown->light(), light);
  EXPECT_EQ(shown->environment(), environment);
  EXPECT_EQ(shown->display(), display);
  EXPECT_EQ(shown->meshSource(), QStringLiteral("sphere"));
  EXPECT_EQ(reopened.document()->undoStack()->count(), 0) << "opening is not an edit";
  EXPECT_EQ(reopened.viewport()->view().light, light);
}

TEST_F(DocumentWorkflow, AGeneratedMapIsWrittenBesideThePresetOnSave) {
  auto flat = std::make_shared<core::Image>(64, 64, 1);
  document()->applyGenerated(core::MapSlot::AmbientOcclusion, flat, QStringLiteral("AO"), {});
  ASSERT_TRUE(m_window->files()->save());
  const std::string written =
      document()->material().map(core::MapSlot::AmbientOcclusion).sourcePath;
  EXPECT_EQ(std::filesystem::path(written).parent_path(),
            std::filesystem::path(m_path).parent_path());
  EXPECT_TRUE(std::filesystem::exists(written));
  // Saving does not add an undo step; the generated map is still undoable.
  EXPECT_EQ(document()->undoStack()->count(), 1);
}

TEST_F(DocumentWorkflow, ClosingWithUnsavedChangesAsks) {
  typeParameter(core::ParamId::HeightScale, 0.06);
  {
    DialogAnswerer cancel(QStringLiteral("Cancel"));
    EXPECT_FALSE(m_window->close());
    EXPECT_EQ(cancel.answered(), 1);
    EXPECT_EQ(cancel.lastBox(), QStringLiteral("unsavedChangesPrompt"));
    EXPECT_TRUE(cancel.lastText().contains(QStringLiteral("bricks.relief")));
  }
  EXPECT_TRUE(m_window->isVisible());
  EXPECT_TRUE(document()->isModified());  // nothing lost
  {
    DialogAnswerer discard(QStringLiteral("Discard"));
    EXPECT_TRUE(m_window->close());
    EXPECT_EQ(discard.answered(), 1);
  }
  // Discarded: the file on disk is as it was.
  core::Result<core::LoadedPreset> onDisk = core::loadPreset(m_path);
  ASSERT_TRUE(onDisk.ok());
  EXPECT_DOUBLE_EQ(onDisk->preset.material.parameter(core::ParamId::HeightScale), 0.03);
}

TEST_F(DocumentWorkflow, NoPromptWithoutChangesAndSaveFromThePrompt) {
  {
    DialogAnswerer any(QStringLiteral("Cancel"));
    EXPECT_TRUE(m_window->files()->newDocument());
    EXPECT_EQ(any.answered(), 0);
  }
  EXPECT_FALSE(document()->material().hasMap(core::MapSlot::Color));
  ASSERT_TRUE(m_window->openPreset(QString::fromStdString(m_path)));
  typeParameter(core::ParamId::Tiling, 5.0);
  {
    DialogAnswerer save(QStringLiteral("Save"));
    EXPECT_TRUE(m_window->files()->newDocument());
    EXPECT_EQ(save.answered(), 1);
  }
  core::Result<core::LoadedPreset> onDisk = core::loadPreset(m_path);
  ASSERT_TRUE(onDisk.ok());
  EXPECT_DOUBLE_EQ(onDisk->preset.material.parameter(core::ParamId::Tiling), 5.0);
}

TEST_F(DocumentWorkflow, RevertReloadsTheSavedFile) {
  typeParameter(core::ParamId::Tiling, 4.0);
  DialogAnswerer discard(QStringLiteral("Discard"));
  EXPECT_TRUE(m_window->files()->revert());
  EXPECT_EQ(discard.answered(), 1);
  EXPECT_DOUBLE_EQ(document()->material().parameter(core::ParamId::Tiling), 2.0);
  EXPECT_FALSE(document()->isModified());
}

TEST_F(DocumentWorkflow, AFailedSaveLeavesTheFileAndTheChanges) {
  const std::string before = readBytes(m_path);
  typeParameter(core::ParamId::Tiling, 6.0);
  // A file where the folder should be: the save cannot even start its temporary file.
  const std::string blocked = scratchFolder() + "/blocked-file";
  std::ofstream(blocked) << "x";
  core::Result<core::SavedPreset> saved =
      document()->save(QString::fromStdString(blocked + "/inside.relief"), core::ViewState{});
  EXPECT_FALSE(saved.ok());
  EXPECT_TRUE(document()->isModified());
  EXPECT_EQ(document()->filePath().toStdString(), m_path);
  EXPECT_EQ(readBytes(m_path), before);
}

TEST_F(DocumentWorkflow, AutosaveIsOfferedAfterACrash) {
  typeParameter(core::ParamId::HeightScale, 0.07);
  ui::RecoveryStore* store = m_window->files()->recovery();
  m_window->files()->autosaveNow();
  ASSERT_TRUE(QTest::qWaitFor([store] { return store->hasAutosave(); }, 10000));
  // A later autosave replaces the earlier one, even when asked while the first is writing.
  typeParameter(core::ParamId::HeightScale, 0.08);
  m_window->files()->autosaveNow();
  const std::string autosaved =
      (store->sessionFolder() + QStringLiteral("/autosave.relief")).toStdString();
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        core::Result<core::LoadedPreset> written = core::loadPreset(autosaved);
        return written && written->preset.material.parameter(core::ParamId::HeightScale) == 0.08;
      },
      10000));

  // A crash leaves the session folder behind with no live lock: copy it as such a folder.
  const QString crashed =
      QFileInfo(store->sessionFolder()).absolutePath() + QStringLiteral("/crashed-session");
  QDir(crashed).removeRecursively();
  QDir().mkpath(crashed);
  QFile::copy(store->sessionFolder() + QStringLiteral("/autosave.relief"),
              crashed + QStringLiteral("/autosave.relief"));
  ASSERT_EQ(ui::RecoveryStore::abandonedWork().size(), 1u);

  // The next start: a fresh window offers it; Recover brings the change back, unsaved.
  ui::MainWindow next;
  next.show();
  {
    DialogAnswerer recover(QStringLiteral("Recover"));
    next.files()->offerRecovery();
    EXPECT_EQ(recover.answered(), 1);
    EXPECT_EQ(recover.lastBox(), QStringLiteral("recoveryPrompt"));
  }
  EXPECT_DOUBLE_EQ(next.document()->material().parameter(core::ParamId::HeightScale), 0.08);
  EXPECT_TRUE(next.document()->isModified());
  EXPECT_EQ(next.document()->filePath().toStdString(), m_path);
  EXPECT_TRUE(next.document()->material().hasMap(core::MapSlot::Height));
  EXPECT_TRUE(ui::RecoveryStore::abandonedWork().empty());  // offered once

  ASSERT_TRUE(m_window->files()->save());
  EXPECT_FALSE(store->hasAutosave());
}

TEST_F(DocumentWorkflow, LibraryListsSamplesAndAppliesParametersAsOneStep) {
  m_window->setBundledPresetFolder(QString::fromStdString(sourcePath("samples")));
  ui::PresetLibrary* library = m_window->presetLibrary();
  QStringList names;
  for (int i = 0; i < library->list()->count(); ++i)
    names << library->list()->item(i)->text();
  EXPECT_TRUE(names.contains(QStringLiteral("bricks")));
  EXPECT_TRUE(names.contains(QStringLiteral("cobblestones")));
  EXPECT_TRUE(names.contains(QStringLiteral("tiles")));

  const core::ParameterValues before = document()->material().parameters();
  const auto colorBefore = document()->material().map(core::MapSlot::Color).image;
  ASSERT_TRUE(library->applyParameters(QString::fromStdString(samplePreset("tiles"))));
  core::Result<core::LoadedPreset> tiles = core::loadPreset(samplePreset("tiles"));
  ASSERT_TRUE(tiles.ok());
  EXPECT_EQ(document()->material().parameters(), tiles->preset.material.parameters());
  // The maps stay: only the look was applied.
  EXPECT_EQ(document()->material().map(core::MapSlot::Color).image, colorBefore);
  EXPECT_EQ(document()->undoStack()->count(), 1);
  document()->undoStack()->undo();
  EXPECT_EQ(document()->material().parameters(), before);

  // Thumbnails arrive from the offscreen renderer: not the flat placeholder.
  ASSERT_TRUE(QTest::qWaitFor(
      [library] {
        const QImage icon =
            library->list()->item(0)->icon().pixmap(ui::PresetLibrary::kThumbnailSize).toImage();
        const QColor centre = icon.pixelColor(icon.width() / 2, icon.height() / 2);
        return centre != QColor(60, 60, 64);
      },
      60000));
}

TEST_F(DocumentWorkflow, ExportDialogWritesAGodotMaterial) {
  const std::string folder = scratchFolder() + "/ui-export";
  ui::ExportDialog dialog(document()->toPreset(core::ViewState{}), m_window->viewDocument()->mesh(),
                          m_window.get());
  dialog.kindBox()->setCurrentIndex(2);
  dialog.folderEdit()->setText(QString::fromStdString(folder));
  DialogAnswerer ok(QStringLiteral("OK"));
  QSignalSpy finished(&dialog, &ui::ExportDialog::exportFinished);
  ASSERT_TRUE(dialog.startExport());
  // The export runs in the background: the dialog can be cancelled while it does.
  EXPECT_TRUE(dialog.isExporting());
  ASSERT_TRUE(finished.wait(60000));
  EXPECT_TRUE(finished.front().front().toBool());
  EXPECT_EQ(ok.answered(), 1);
  EXPECT_TRUE(std::filesystem::exists(folder + "/bricks.tres"));
  EXPECT_EQ(dialog.writtenPath().toStdString(), folder + "/bricks.tres");
  // The next export offers the same target (and would the next run: QSettings).
  const QString godot = dialog.kindBox()->currentText();
  ui::ExportDialog again(document()->toPreset(core::ViewState{}), m_window->viewDocument()->mesh(),
                         m_window.get());
  EXPECT_EQ(again.kindBox()->currentIndex(), 2);
  EXPECT_EQ(again.kindBox()->currentText(), godot);
}

// Cancel stops a running export without closing the dialog: no preset is written (it is the
// last file a package writes) and Export can be pressed again.
TEST_F(DocumentWorkflow, ExportCanBeCancelledWhileItRuns) {
  const std::string folder = scratchFolder() + "/ui-export-cancelled";
  core::Preset preset = document()->toPreset(core::ViewState{});
  // ASTC 4x4 at best quality takes seconds for the 1024x1024 colour map: time to cancel.
  preset.compression[std::size_t(core::MapSlot::Color)] =
      core::CompressionSettings{core::TextureFormat::Astc4x4, core::CompressionQuality::Best, true};
  ui::ExportDialog dialog(preset, m_window->viewDocument()->mesh(), m_window.get());
  dialog.kindBox()->setCurrentIndex(int(core::ExportKind::Package));
  dialog.folderEdit()->setText(QString::fromStdString(folder));
  QSignalSpy finished(&dialog, &ui::ExportDialog::exportFinished);
  ASSERT_TRUE(dialog.startExport());
  QTest::mouseClick(dialog.cancelButton(), Qt::LeftButton);
  ASSERT_TRUE(finished.wait(60000));
  EXPECT_FALSE(finished.front().front().toBool());
  EXPECT_FALSE(dialog.isExporting());
  EXPECT_FALSE(std::filesystem::exists(folder + "/bricks.relief"));
  EXPECT_TRUE(dialog.writtenPath().isEmpty());
  EXPECT_NE(dialog.result(), QDialog::Accepted);
}

TEST_F(DocumentWorkflow, ViewportImageAtAnySize) {
  const std::string path = scratchFolder() + "/viewport.png";
  ASSERT_TRUE(m_window->saveViewportImage(QString::fromStdString(path), 640, 200));
  core::Result<core::Image> image = core::loadImage(path);
  ASSERT_TRUE(image.ok()) << image.error();
  EXPECT_EQ(image->width(), 640);
  EXPECT_EQ(image->height(), 200);
}

TEST_F(DocumentWorkflow, ShortcutListShowsTheMenusShortcuts) {
  ui::ShortcutsDialog dialog(m_window->menuBar(), QStringLiteral("drag"));
  auto* tree = dialog.findChild<QTreeWidget*>(QStringLiteral("shortcutList"));
  ASSERT_NE(tree, nullptr);
  QStringList rows;
  for (QTreeWidgetItemIterator it(tree); *it; ++it)
    rows << (*it)->text(0) + QLatin1Char('=') + (*it)->text(1);
  const QString all = rows.join(QLatin1Char('\n'));
  for (const char* expected :
       {"Save=Ctrl+S", "Save As=Ctrl+Shift+S", "New=Ctrl+N", "Undo=Ctrl+Z", "Export=Ctrl+E"}) {
    EXPECT_TRUE(all.contains(QString::fromLatin1(expected))) << expected << "\n"
                                                             << all.toStdString();
  }
}

}  // namespace
}  // namespace relief::test
