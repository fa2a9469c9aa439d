// The view document (ui/document/ViewDocument): its edits are undo steps on the material
// document's stack, a drag is one step, a preset's view is shown without one, and the Light
// panel follows it with no viewport at all.
#include "ui/document/ViewDocument.h"
#include "ui/panels/EnvironmentPanel.h"
#include "ui/panels/LightPanel.h"
#include "ui/panels/ParameterSlider.h"

#include "core/compression/TextureFile.h"
#include "core/shading/EnvironmentMaps.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>

#include <gtest/gtest.h>

namespace relief::test {
namespace {

core::DirectionalLight lightAt(float azimuth, float elevation) {
  core::DirectionalLight light;
  light.azimuthDeg = azimuth;
  light.elevationDeg = elevation;
  return light;
}

TEST(ViewDocument, LightEditsAreUndoStepsAndADragIsOne) {
  QUndoStack stack;
  ui::ViewDocument view(&stack);
  const core::DirectionalLight start = view.light();
  view.setLight(lightAt(100.0f, 40.0f));
  EXPECT_EQ(stack.count(), 1);
  view.setLight(view.light());
  EXPECT_EQ(stack.count(), 1) << "an unchanged light is no step";
  // A drag: every move of one interactive edit merges into one step.
  const int drag = view.beginInteractiveEdit();
  for (int i = 1; i <= 10; ++i)
    view.setLight(lightAt(100.0f + float(i), 40.0f - float(i)), drag);
  EXPECT_EQ(stack.count(), 2);
  EXPECT_EQ(view.light(), lightAt(110.0f, 30.0f));
  QSignalSpy changed(&view, &ui::ViewDocument::lightChanged);
  stack.undo();
  EXPECT_EQ(view.light(), lightAt(100.0f, 40.0f)) << "the whole drag is undone at once";
  stack.undo();
  EXPECT_EQ(view.light(), start);
  EXPECT_EQ(changed.count(), 2);
  stack.redo();
  stack.redo();
  EXPECT_EQ(view.light(), lightAt(110.0f, 30.0f));
}

TEST(ViewDocument, EnvironmentDisplayAndMeshEditsAreUndone) {
  QUndoStack stack;
  ui::ViewDocument view(&stack);
  const core::Environment environment = view.environment();
  const core::DisplayTransform display = view.display();
  core::Environment sky = environment;
  sky.source = "sky";
  sky.rotationDeg = 45.0f;
  view.setEnvironment(sky);
  core::DisplayTransform brighter = display;
  brighter.exposureEv = 1.5f;
  view.setDisplay(brighter);
  ASSERT_TRUE(view.showMesh(QStringLiteral("sphere")));
  EXPECT_EQ(view.meshSource(), QStringLiteral("sphere"));
  EXPECT_TRUE(view.framingPending()) << "a new mesh is framed";
  EXPECT_EQ(stack.count(), 3);
  stack.undo();
  EXPECT_EQ(view.meshSource(), QStringLiteral("plane"));
  stack.undo();
  EXPECT_EQ(view.display(), display);
  EXPECT_EQ(view.environment(), sky);
  stack.undo();
  EXPECT_EQ(view.environment(), environment);
  // A mesh that cannot be loaded is an error naming the file, and no step.
  const auto missing = view.showMesh(QStringLiteral("/nonexistent/rock.obj"));
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("rock.obj"), std::string::npos) << missing.error();
  EXPECT_EQ(stack.index(), 0);
}

TEST(ViewDocument, CameraAndDebugViewAreNavigationNotUndoSteps) {
  QUndoStack stack;
  ui::ViewDocument view(&stack);
  core::OrbitCamera camera = view.camera();
  camera.orbit(30.0f, 10.0f);
  QSignalSpy cameraSpy(&view, &ui::ViewDocument::cameraChanged);
  view.setCamera(camera);
  view.setDebugView(core::DebugView::Steps);
  EXPECT_EQ(stack.count(), 0);
  EXPECT_EQ(cameraSpy.count(), 1);
  EXPECT_FLOAT_EQ(view.camera().yawDeg, camera.yawDeg);
  EXPECT_EQ(view.debugView(), core::DebugView::Steps);
}

TEST(ViewDocument, APresetsViewIsShownWithoutAnUndoStep) {
  QUndoStack stack;
  ui::ViewDocument view(&stack);
  core::ViewState state;
  state.light = lightAt(200.0f, 20.0f);
  state.mesh = "cube";
  core::DisplayTransform display;
  display.toneMapper = core::ToneMapper::Aces;
  state.display = display;
  ASSERT_TRUE(view.showViewState(state));
  EXPECT_EQ(stack.count(), 0);
  EXPECT_EQ(view.light(), *state.light);
  EXPECT_EQ(view.meshSource(), QStringLiteral("cube"));
  EXPECT_EQ(view.display(), display);
  EXPECT_TRUE(view.framingPending()) << "no camera saved: the mesh is framed";
  // What it shows is what a save stores.
  const core::ViewState saved = view.viewState();
  EXPECT_EQ(saved.light, state.light);
  EXPECT_EQ(saved.mesh, "cube");
  EXPECT_EQ(saved.display, state.display);
}

// The panels hold a view document and no viewport: they and whatever else edits the document
// (the viewport's Ctrl+drag, undo, a preset) stay in step through it.
TEST(ViewDocument, LightPanelEditsAndFollowsTheDocument) {
  QUndoStack stack;
  ui::ViewDocument view(&stack);
  ui::LightPanel panel(&view);
  view.setLight(lightAt(120.0f, 25.0f));
  EXPECT_EQ(panel.azimuthControl()->value(), 120.0);
  EXPECT_EQ(panel.elevationControl()->value(), 25.0);

  panel.intensityBox()->setValue(2.0);
  EXPECT_FLOAT_EQ(view.light().intensity, 2.0f);
  panel.exposureBox()->setValue(1.0);
  EXPECT_FLOAT_EQ(view.display().exposureEv, 1.0f);
  EXPECT_EQ(stack.count(), 3);
  stack.undo();
  stack.undo();
  EXPECT_EQ(panel.intensityBox()->value(), view.light().intensity) << "undo reaches the panel";
  EXPECT_EQ(panel.exposureBox()->value(), 0.0);

  // A light put below the horizon (by a preset) ticks the panel's box and lets Ctrl+drag follow.
  ASSERT_TRUE(
      view.showViewState({std::nullopt, lightAt(90.0f, -20.0f), "", std::nullopt, std::nullopt}));
  EXPECT_TRUE(panel.belowHorizonBox()->isChecked());
  EXPECT_TRUE(view.lightBelowHorizonAllowed());
  EXPECT_EQ(panel.elevationControl()->value(), -20.0);

  core::Environment environment = view.environment();
  environment.rotationDeg = 90.0f;
  view.setEnvironment(environment);
  EXPECT_EQ(panel.environmentPanel()->rotationControl()->value(), 90.0);
}

// Save as BC6H: the studio environment compressed off the GUI thread into a KTX2 file that
// decodes as BC6H, the material lit by that file as one undo step (undo returns to the studio),
// and the note states the file's size and its error in float (the studio's 12 stops kept to
// within a hundredth of a stop on average). A path that is not .ktx2 or .dds is refused and
// changes nothing.
TEST(ViewDocument, EnvironmentSavedAsBc6hLightsTheMaterialAsOneStep) {
  QUndoStack stack;
  ui::ViewDocument view(&stack);
  ui::EnvironmentPanel panel(&view);
  QTemporaryDir folder;
  ASSERT_TRUE(folder.isValid());
  const QString path = folder.filePath(QStringLiteral("studio_bc6h.ktx2"));
  QSignalSpy saved(&panel, &ui::EnvironmentPanel::compressedSaved);
  panel.saveCompressed(path);
  ASSERT_TRUE(saved.wait(120000));
  ASSERT_TRUE(saved.front().at(0).toBool()) << saved.front().at(1).toString().toStdString();
  EXPECT_EQ(view.environment().source, path.toStdString());
  EXPECT_EQ(stack.count(), 1);
  const core::Result<core::CompressedTexture> texture =
      core::loadCompressedTexture(path.toStdString());
  ASSERT_TRUE(texture.ok()) << texture.error();
  EXPECT_EQ(texture->format, core::TextureFormat::Bc6h);
  EXPECT_GT(texture->levels.size(), 5u) << "with mipmaps";
  EXPECT_TRUE(core::environmentRadiance(path.toStdString()).ok());
  const QString note = panel.compressedNote()->text();
  EXPECT_TRUE(note.contains(QStringLiteral("exposure PSNR"))) << note.toStdString();
  stack.undo();
  EXPECT_EQ(view.environment().source, "studio");

  saved.clear();
  // The refusal's message box is closed as soon as it shows.
  QTimer closer;
  QObject::connect(&closer, &QTimer::timeout, [] {
    if (QWidget* box = QApplication::activeModalWidget())
      box->close();
  });
  closer.start(50);
  panel.saveCompressed(folder.filePath(QStringLiteral("studio.png")));
  ASSERT_TRUE(saved.wait(60000));
  EXPECT_FALSE(saved.front().at(0).toBool());
  EXPECT_TRUE(saved.front().at(1).toString().contains(QStringLiteral(".ktx2 or .dds")));
  EXPECT_EQ(view.environment().source, "studio");
  EXPECT_TRUE(panel.saveCompressedButton()->isEnabled());
}

}  // namespace
}  // namespace relief::test
