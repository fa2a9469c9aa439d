// Every control of the viewport's material, light and view, driven through the real widgets:
// each must change the next frame (checked on the grabbed framebuffer), and nothing redraws
// when nothing changed.
#include "core/image/ColorSpace.h"
#include "core/image/ImageIO.h"
#include "core/tracing/UvErrorMap.h"
#include "renderer/ImageConversion.h"
#include "support/DialogAnswerer.h"
#include "support/ImageCompare.h"
#include "support/MainWindowFixture.h"
#include "support/TestPaths.h"
#include "ui/document/MaterialDocument.h"
#include "ui/document/ViewDocument.h"
#include "ui/panels/CompressPanel.h"
#include "ui/panels/EnvironmentPanel.h"
#include "ui/panels/LightPanel.h"
#include "ui/panels/ParameterPanel.h"
#include "ui/panels/ParameterSlider.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/CostTableWindow.h"
#include "ui/window/EngineGridWindow.h"
#include "ui/window/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QSlider>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>

namespace relief::test {
namespace {

using core::ParamId;

class ViewportControls : public MainWindowFixture {
 protected:
  void SetUp() override {
    openWindow(1100, 700, samplePreset("cobblestones"));
    viewDocument()->setDebugView(core::DebugView::Shading);
  }

  QWidget* editor(ParamId id) { return m_window->parameterPanel()->editor(id); }

  // Moves one parameter's control to another value, as a user would.
  void changeThroughItsControl(ParamId id) {
    const core::ParameterSpec& spec = core::parameterSpec(id);
    QWidget* control = editor(id);
    ASSERT_TRUE(control->isEnabled()) << spec.name << " is disabled in this set-up";
    if (auto* slider = qobject_cast<ui::ParameterSlider*>(control)) {
      // Counts go to an extreme (a few more samples change few pixels); values move by 30%.
      const double current = document()->material().parameter(id);
      double target = current < (spec.minimum + spec.maximum) / 2
                          ? current + 0.3 * (spec.maximum - spec.minimum)
                          : current - 0.3 * (spec.maximum - spec.minimum);
      if (spec.kind == core::ParamKind::Int) {
        target = current > spec.minimum ? spec.minimum : spec.maximum;
      }
      // The fewest samples is a floor under the count by texels crossed: at this close, low
      // view every ray crosses more texels than 8, so only raising it shows.
      if (id == ParamId::MinSamples)
        target = spec.maximum;
      slider->spinBox()->setValue(target);
    } else if (auto* check = qobject_cast<QCheckBox*>(control)) {
      QTest::mouseClick(check, Qt::LeftButton);
    } else if (auto* combo = qobject_cast<QComboBox*>(control)) {
      const int next = (combo->currentIndex() + 1) % combo->count();
      combo->setCurrentIndex(next);
      Q_EMIT combo->activated(next);
    }
  }
};

// The frame changed visibly somewhere. Rendering is deterministic (undo gives back the same
// bits), so any difference is the control's effect; some act on few pixels (a shadow edge,
// a few more samples), so no mean is required.
::testing::AssertionResult frameChanged(const core::Image& before, const core::Image& after) {
  const ImageDifference change = compareImages(before, after);
  if (change.maxError > 3.0 / 255.0)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "max change " << change.maxError * 255.0 << "/255";
}

TEST_F(ViewportControls, EveryParameterChangesTheFrame) {
  // Relief mapping with soft shadows: every parameter but one is in use. Close, low camera
  // and a low light, where samples and shadows matter most.
  document()->setTechnique(core::Technique::Relief);
  core::OrbitCamera camera = viewDocument()->camera();
  camera.pitchDeg = 20.0f;
  camera.distance = 0.9f;
  viewDocument()->setCamera(camera);
  core::DirectionalLight light = viewDocument()->light();
  light.elevationDeg = 15.0f;
  viewDocument()->setLight(light);
  for (const core::ParameterSpec& spec : core::allParameters()) {
    SCOPED_TRACE(std::string(spec.name));
    // Max tessellation is the displacement technique's alone.
    document()->setTechnique(spec.use == core::ParamUse::Tessellation
                                 ? core::Technique::Displacement
                                 : core::Technique::Relief);
    // Metallic and roughness are pbr shading's; the others are seen under classic.
    document()->setParameter(ParamId::Shading, double(int(spec.use == core::ParamUse::Pbr
                                                              ? core::ShadingModel::Pbr
                                                              : core::ShadingModel::Classic)));
    // Write-displaced-depth changes only depth: watch it in the depth view.
    viewDocument()->setDebugView(spec.id == ParamId::DepthOffset ? core::DebugView::Depth
                                                                 : core::DebugView::Shading);
    // Silhouettes change curved meshes' outlines alone: watch the framed sphere.
    const bool onSphere = spec.id == ParamId::CurvedSilhouettes;
    if (onSphere) {
      ASSERT_TRUE(viewDocument()->showMesh(QStringLiteral("sphere")).ok());
    }
    const core::Image before = grabbed();
    changeThroughItsControl(spec.id);
    EXPECT_TRUE(frameChanged(before, grabbed()));
    document()->undoStack()->undo();
    EXPECT_EQ(compareImages(before, grabbed()).maxError, 0.0) << "undo restores";
    if (onSphere) {
      ASSERT_TRUE(viewDocument()->showMesh(QStringLiteral("plane")).ok());
      viewDocument()->setCamera(camera);
    }
  }
}

TEST_F(ViewportControls, EveryTechniqueAndDebugViewChangesTheFrame) {
  QComboBox* techniques = m_window->parameterPanel()->techniqueBox();
  core::Image previous = grabbed();
  for (int i = 1; i < techniques->count(); ++i) {
    techniques->setCurrentIndex(i);
    QSignalSpy coneBuilds(viewport(), &ui::ViewportWidget::coneMapBuilding);
    Q_EMIT techniques->activated(i);
    core::Image frame = grabbed();
    if (!coneBuilds.isEmpty()) {  // the cone technique: its frames once its cone map is built
      EXPECT_TRUE(QTest::qWaitFor([&] { return coneBuilds.count() >= 2; }, 20000));
      frame = grabbed();
    }
    EXPECT_TRUE(frameChanged(previous, frame)) << techniques->itemText(i).toStdString();
    previous = frame;
  }
  QComboBox* views = m_window->debugViewBox();
  for (int i = 1; i < views->count(); ++i) {
    if (views->itemData(i).toString() == QStringLiteral("error"))
      continue;  // asynchronous
    views->setCurrentIndex(i);
    Q_EMIT views->activated(i);
    const core::Image frame = grabbed();
    EXPECT_TRUE(frameChanged(previous, frame)) << views->itemText(i).toStdString();
    previous = frame;
  }
}

// The cone map is built off the GUI thread: choosing the cone technique draws at once (with the
// quadtree, which finds the same exact surface), says so in the status bar, and draws with the
// cones once they are built. Where the map is minified the two differ (the quadtree takes the
// top of the block a ray enters, the cone technique the block it steps into), so the frame
// changes when the cones arrive.
TEST_F(ViewportControls, TheConeMapIsBuiltOffTheGuiThreadWhileTheQuadtreeDraws) {
  document()->setTechnique(core::Technique::Quadtree);
  const core::Image quadtree = grabbed();
  QSignalSpy coneBuilds(viewport(), &ui::ViewportWidget::coneMapBuilding);
  document()->setTechnique(core::Technique::Cone);
  const core::Image standIn = grabbed();
  ASSERT_EQ(coneBuilds.count(), 1);
  EXPECT_TRUE(coneBuilds.at(0).at(0).toBool());
  EXPECT_TRUE(m_window->statusBar()->currentMessage().contains(QStringLiteral("cone map")));
  EXPECT_LT(compareImages(quadtree, standIn).maxError, 1.0 / 255.0);
  ASSERT_TRUE(QTest::qWaitFor([&] { return coneBuilds.count() >= 2; }, 20000));
  EXPECT_FALSE(coneBuilds.at(1).at(0).toBool());
  const core::Image cones = grabbed();
  EXPECT_TRUE(frameChanged(standIn, cones));
  // Built once per height map: back and forth draws at once.
  document()->setTechnique(core::Technique::Pom);
  grabbed();
  document()->setTechnique(core::Technique::Cone);
  EXPECT_LT(compareImages(grabbed(), cones).maxError, 1.0 / 255.0);
  EXPECT_EQ(coneBuilds.count(), 2);
}

TEST_F(ViewportControls, LightControlsMoveTheLight) {
  ui::LightPanel* light = m_window->lightPanel();
  core::Image before = grabbed();
  light->azimuthSlider()->setValue((light->azimuthSlider()->value() + 120) % 360);
  core::Image after = grabbed();
  EXPECT_TRUE(frameChanged(before, after));
  light->elevationSlider()->setValue(light->elevationSlider()->value() + 30);
  before = after;
  after = grabbed();
  EXPECT_TRUE(frameChanged(before, after));
  light->intensityBox()->setValue(0.5);
  before = after;
  after = grabbed();
  EXPECT_TRUE(frameChanged(before, after));
  // The ambient is classic shading's (pbr takes it from the environment).
  document()->setParameter(ParamId::Shading, double(int(core::ShadingModel::Classic)));
  before = grabbed();
  light->ambientBox()->setValue(0.5);
  after = grabbed();
  EXPECT_TRUE(frameChanged(before, after));
  light->exposureBox()->setValue(1.0);
  before = after;
  after = grabbed();
  EXPECT_TRUE(frameChanged(before, after));
  light->toneMapperBox()->setCurrentIndex(1);
  EXPECT_EQ(viewport()->view().display.toneMapper, core::ToneMapper::PbrNeutral);
  before = after;
  after = grabbed();
  EXPECT_TRUE(frameChanged(before, after));
  EXPECT_EQ(viewDocument()->viewState().display->exposureEv, 1.0f);  // presets save it
  // Ctrl+drag in the viewport moves the same light, and the panel follows.
  const int azimuth = light->azimuthSlider()->value();
  const QPoint centre = viewport()->rect().center();
  QTest::mousePress(viewport(), Qt::LeftButton, Qt::ControlModifier, centre);
  QTest::mouseMove(viewport(), centre + QPoint(60, 0));
  QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::ControlModifier, centre + QPoint(60, 0));
  EXPECT_NE(light->azimuthSlider()->value(), azimuth);
}

// The heat-map legend is drawn in its colours in the viewport (it was once drawn grey there,
// while the CLI's was coloured): its blue and red ends are found in the frame's corner.
TEST_F(ViewportControls, HeatmapLegendIsDrawnInColour) {
  viewDocument()->setDebugView(core::DebugView::Steps);
  const core::Image frame = grabbed();
  int red = 0, blue = 0;
  for (int y = frame.height() * 4 / 5; y < frame.height(); ++y) {
    for (int x = frame.width() / 2; x < frame.width(); ++x) {
      const float r = frame.at(x, y, 0), g = frame.at(x, y, 1), b = frame.at(x, y, 2);
      red += r > 0.7f && g < 0.35f && b < 0.35f ? 1 : 0;
      blue += b > 0.5f && r < 0.2f && g < 0.3f ? 1 : 0;
    }
  }
  EXPECT_GT(red, 20);
  EXPECT_GT(blue, 20);
}

// The light's elevation runs from the horizon to overhead, takes typed values, and goes below
// the horizon only when asked (where the panel warns that the surface is unlit); Ctrl+drag in
// the viewport stops at the horizon too.
TEST_F(ViewportControls, LightElevationStaysAboveTheHorizonUnlessAsked) {
  ui::LightPanel* light = m_window->lightPanel();
  QDoubleSpinBox* elevation = light->elevationControl()->spinBox();
  EXPECT_EQ(elevation->minimum(), 0.0);
  EXPECT_EQ(elevation->maximum(), 90.0);
  elevation->selectAll();
  QTest::keyClicks(elevation, QStringLiteral("60"));
  QTest::keyClick(elevation, Qt::Key_Return);
  EXPECT_FLOAT_EQ(viewport()->view().light.elevationDeg, 60.0f);
  EXPECT_EQ(light->elevationSlider()->value(), 60);  // the slider follows the typed value

  const QPoint centre = viewport()->rect().center();
  QTest::mousePress(viewport(), Qt::LeftButton, Qt::ControlModifier, centre);
  QTest::mouseMove(viewport(), centre + QPoint(0, 150));
  QTest::mouseMove(viewport(), centre + QPoint(0, 300));
  QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::ControlModifier, centre + QPoint(0, 300));
  EXPECT_EQ(viewport()->view().light.elevationDeg, 0.0f) << "Ctrl+drag stops at the horizon";
  EXPECT_FALSE(light->belowHorizonWarning()->isVisibleTo(light));

  light->belowHorizonBox()->setChecked(true);
  EXPECT_EQ(elevation->minimum(), -90.0);
  elevation->setValue(-20.0);
  EXPECT_FLOAT_EQ(viewport()->view().light.elevationDeg, -20.0f);
  EXPECT_TRUE(light->belowHorizonWarning()->isVisibleTo(light));
  light->belowHorizonBox()->setChecked(false);
  EXPECT_EQ(viewport()->view().light.elevationDeg, 0.0f) << "back above the horizon";
  EXPECT_FALSE(light->belowHorizonWarning()->isVisibleTo(light));
}

// Shift while dragging a parameter's slider moves it a tenth as fast: 100 pixels with Shift go
// as far as 10 without.
TEST_F(ViewportControls, ShiftDragMovesASliderATenthAsFast) {
  auto* control = qobject_cast<ui::ParameterSlider*>(editor(ParamId::HeightScale));
  ASSERT_NE(control, nullptr);
  QSlider* slider = control->slider();
  const int start = slider->value();
  const double positionsPerPixel =
      double(slider->maximum() - slider->minimum()) / double(slider->width());
  slider->setSliderDown(true);
  const auto shiftMove = [slider](int x) {
    const QPointF at(x, slider->height() / 2);
    QMouseEvent move(QEvent::MouseMove, at, slider->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                     Qt::ShiftModifier);
    QApplication::sendEvent(slider, &move);
  };
  shiftMove(20);
  shiftMove(120);
  slider->setSliderDown(false);
  const double expected = 100.0 * positionsPerPixel / ui::ParameterSlider::kFineDragFactor;
  EXPECT_NEAR(slider->value() - start, expected, 1.0);
  EXPECT_NEAR(document()->material().parameter(ParamId::HeightScale), control->value(), 1e-9);
}

// The environment controls: each built-in, the intensity, the rotation and the backgrounds
// change the frame of a pbr material; a file that is no environment is refused by name in a
// message box and leaves the environment as it was; a good EXR is shown and offered again.
TEST_F(ViewportControls, EnvironmentControlsChangeThePbrFrame) {
  document()->setParameter(ParamId::Shading, double(int(core::ShadingModel::Pbr)));
  ui::EnvironmentPanel* panel = m_window->lightPanel()->environmentPanel();
  QComboBox* sources = panel->sourceBox();
  core::Image previous = grabbed();
  const auto expectChange = [&](const char* what) {
    core::Image next = grabbed();
    EXPECT_TRUE(frameChanged(previous, next)) << what;
    previous = std::move(next);
  };
  for (int i = 0; i < sources->count(); ++i) {
    const QString name = sources->itemData(i).toString();
    if (name.isEmpty() || name == QString::fromStdString(viewport()->view().environment.source))
      continue;  // "File…", or the one shown
    sources->setCurrentIndex(i);
    Q_EMIT sources->activated(i);
    EXPECT_EQ(viewport()->view().environment.source, name.toStdString());
    expectChange(qPrintable(name));
  }
  // Back to the studio, whose light has a direction (the uniform white has none to rotate).
  sources->setCurrentIndex(sources->findData(QStringLiteral("studio")));
  Q_EMIT sources->activated(sources->currentIndex());
  expectChange("studio");
  panel->intensityBox()->setValue(2.0);
  expectChange("intensity");
  panel->rotationControl()->spinBox()->setValue(90);
  expectChange("rotation");
  for (int i = 0; i < panel->backgroundBox()->count(); ++i) {
    if (i == panel->backgroundBox()->currentIndex())
      continue;
    panel->backgroundBox()->setCurrentIndex(i);
    expectChange(qPrintable(panel->backgroundBox()->currentText()));
  }
  EXPECT_EQ(viewDocument()->viewState().environment->rotationDeg, 90.0f);  // presets save it

  // A square EXR is not an equirectangular map: refused, the environment kept.
  const core::Environment kept = viewport()->view().environment;
  const std::string square = scratchFolder() + "/square.exr";
  core::Image pixels(16, 16, 3);
  ASSERT_TRUE(core::saveImage(pixels, square, core::SampleFormat::Half).ok());
  DialogAnswerer answerer(QStringLiteral("OK"));
  QSignalSpy loaded(panel, &ui::EnvironmentPanel::fileLoaded);
  panel->loadFile(QString::fromStdString(square));
  ASSERT_TRUE(loaded.wait(10000));
  EXPECT_FALSE(loaded.at(0).at(0).toBool());
  EXPECT_TRUE(loaded.at(0).at(1).toString().contains(QString::fromStdString(square)));
  EXPECT_EQ(answerer.answered(), 1);
  EXPECT_EQ(viewport()->view().environment, kept);

  const std::string good = scratchFolder() + "/good.exr";
  core::Image wide(32, 16, 3);
  for (int x = 0; x < 32; ++x)
    wide.at(x, 4, 0) = 8.0f;
  ASSERT_TRUE(core::saveImage(wide, good, core::SampleFormat::Half).ok());
  panel->loadFile(QString::fromStdString(good));
  ASSERT_TRUE(loaded.wait(10000));
  EXPECT_TRUE(loaded.at(1).at(0).toBool());
  EXPECT_EQ(viewport()->view().environment.source, good);
  EXPECT_GE(sources->findData(QString::fromStdString(good)), 0);
  expectChange("file");
}

// The display and the environment are remembered for the next run, as the light is: closing
// the window saves them and a new window starts with them, the Environment group showing them.
// A remembered file that has gone gives the studio.
TEST_F(ViewportControls, TheDisplayAndEnvironmentAreRememberedForTheNextRun) {
  core::Environment environment;
  environment.source = "sky";
  environment.intensity = 2.5f;
  environment.rotationDeg = 45.0f;
  environment.background = core::Background::Blurred;
  core::DisplayTransform display;
  display.exposureEv = 1.5f;
  display.toneMapper = core::ToneMapper::Aces;
  viewDocument()->setEnvironment(environment);
  viewDocument()->setDisplay(display);
  // The environment is part of the preset's view, so the edit asks before closing; the settings
  // remember it for the next run whatever the answer.
  EXPECT_TRUE(document()->isModified());
  {
    DialogAnswerer discard(QStringLiteral("Discard"));
    ASSERT_TRUE(m_window->close());
    EXPECT_EQ(discard.answered(), 1);
  }

  ui::MainWindow next;
  EXPECT_EQ(next.viewport()->view().environment, environment);
  EXPECT_EQ(next.viewport()->view().display, display);
  EXPECT_EQ(next.lightPanel()->environmentPanel()->sourceBox()->currentData().toString(),
            QStringLiteral("sky"));

  environment.source = scratchFolder() + "/gone.exr";
  next.viewDocument()->setEnvironment(environment);
  {
    DialogAnswerer discard(QStringLiteral("Discard"));
    ASSERT_TRUE(next.close());
  }
  ui::MainWindow third;
  EXPECT_EQ(third.viewport()->view().environment.source, "studio");
}

TEST_F(ViewportControls, MeshesAndTheSplitComparisonChangeTheFrame) {
  QComboBox* meshes = m_window->meshBox();
  core::Image previous = grabbed();
  for (int i = 1; i < meshes->count(); ++i) {
    meshes->setCurrentIndex(i);
    Q_EMIT meshes->activated(i);
    const core::Image frame = grabbed();
    EXPECT_TRUE(frameChanged(previous, frame)) << meshes->itemText(i).toStdString();
    previous = frame;
  }
  // A/B: hold the current material as B, change A, and the two halves differ.
  m_window->compareAction()->setChecked(true);
  ASSERT_TRUE(viewport()->isComparing());
  document()->setTechnique(core::Technique::Normal);
  const core::Image split = grabbed();
  ASSERT_NE(viewport()->comparisonMaterial(), nullptr);
  EXPECT_EQ(viewport()->comparisonMaterial()->technique(), core::Technique::Pom);
  // Moving the divider moves where B starts.
  viewport()->setDividerFraction(0.2f);
  EXPECT_TRUE(frameChanged(split, grabbed()));
}

TEST_F(ViewportControls, NothingRedrawsWhenNothingChanged) {
  grabbed();
  QTest::qWait(100);
  QSignalSpy frames(viewport(), &ui::ViewportWidget::frameRendered);
  QTest::qWait(400);
  EXPECT_EQ(frames.count(), 0);
  core::DirectionalLight light = viewDocument()->light();
  light.azimuthDeg += 1.0f;
  viewDocument()->setLight(light);  // a change request: one redraw
  QTest::qWait(200);
  EXPECT_GE(frames.count(), 1);
}

// The Distance box and ] / [ look from farther (a view option: no undo step); the Compress
// panel's Mipmaps and Mip filter write one chain into every compression choice (one undo step
// each) and the viewport samples that chain: without mipmaps the far frame changes.
TEST_F(ViewportControls, DistanceAndTheShippedMipChain) {
  m_window->resize(500, 400);
  const core::Image near = grabbed();
  const int undoSteps = document()->undoStack()->count();
  auto* distance = m_window->findChild<QComboBox*>(QStringLiteral("viewDistance"));
  ASSERT_NE(distance, nullptr);
  const int eight = distance->findData(8);
  ASSERT_GE(eight, 0);
  distance->setCurrentIndex(eight);
  Q_EMIT distance->activated(eight);
  EXPECT_EQ(viewDocument()->viewDistance(), 8);
  EXPECT_EQ(viewport()->frameSettings().tiles.distance, 8);
  const core::Image far = grabbed();
  EXPECT_TRUE(frameChanged(near, far));
  EXPECT_EQ(document()->undoStack()->count(), undoSteps) << "a view option, not an edit";
  auto* farther = m_window->findChild<QAction*>(QStringLiteral("fartherAction"));
  auto* closer = m_window->findChild<QAction*>(QStringLiteral("closerAction"));
  ASSERT_TRUE(farther && closer);
  EXPECT_EQ(farther->shortcut(), QKeySequence(QStringLiteral("]")));
  farther->trigger();
  EXPECT_EQ(viewDocument()->viewDistance(), 16);
  EXPECT_EQ(distance->currentData().toInt(), 16);
  closer->trigger();
  EXPECT_EQ(viewDocument()->viewDistance(), 8);

  ui::CompressPanel* panel = m_window->compressPanel();
  document()->setCompression(
      core::MapSlot::Color,
      core::CompressionSettings{core::TextureFormat::Bc1, core::CompressionQuality::Fast, true});
  const auto colourChain = [&] {
    return viewport()->frameSettings().mipChains[std::size_t(core::MapSlot::Color)];
  };
  EXPECT_EQ(colourChain(), (core::MipChainSpec{true, core::MipFilter::Box}));
  const int kaiser = panel->mipFilterBox()->findData(int(core::MipFilter::Kaiser));
  panel->mipFilterBox()->setCurrentIndex(kaiser);
  Q_EMIT panel->mipFilterBox()->activated(kaiser);
  EXPECT_EQ(document()->compression(core::MapSlot::Color)->mipFilter, core::MipFilter::Kaiser);
  EXPECT_EQ(colourChain(), (core::MipChainSpec{true, core::MipFilter::Kaiser}));
  const core::Image kaiserFrame = grabbed();
  const int beforeMipmaps = document()->undoStack()->count();
  panel->mipmapsBox()->setChecked(false);
  EXPECT_EQ(document()->undoStack()->count(), beforeMipmaps + 1);
  EXPECT_FALSE(colourChain().mipmaps);
  EXPECT_FALSE(panel->mipFilterBox()->isEnabled());
  EXPECT_TRUE(frameChanged(kaiserFrame, grabbed())) << "level 0 alone aliases far away";
  document()->undoStack()->undo();
  EXPECT_TRUE(colourChain().mipmaps);
  EXPECT_TRUE(panel->mipmapsBox()->isChecked()) << "the box follows the document";

  // Roughness from normals: only for a compressed roughness map with a normal map beside it; it
  // writes the roughness choice (one undo step) and the viewport samples the folded chain.
  QCheckBox* fold = panel->roughnessFoldBox();
  EXPECT_FALSE(fold->isEnabled()) << "no roughness map yet";
  const core::Image& normals = *document()->material().image(core::MapSlot::Normal);
  auto roughness = std::make_shared<core::Image>(normals.width(), normals.height(), 1);
  for (std::size_t i = 0; i < roughness->valueCount(); ++i)
    roughness->data()[i] = 0.25f;
  document()->setMap(core::MapSlot::Roughness, roughness, QString());
  document()->setCompression(
      core::MapSlot::Roughness,
      core::CompressionSettings{core::TextureFormat::Bc4, core::CompressionQuality::Fast, true});
  ASSERT_TRUE(fold->isEnabled());
  const core::Image plainFrame = grabbed();
  const int beforeFold = document()->undoStack()->count();
  fold->setChecked(true);
  EXPECT_EQ(document()->undoStack()->count(), beforeFold + 1);
  EXPECT_TRUE(document()->compression(core::MapSlot::Roughness)->roughnessFromNormals);
  EXPECT_TRUE(viewport()
                  ->frameSettings()
                  .mipChains[std::size_t(core::MapSlot::Roughness)]
                  .foldNormalSpread);
  EXPECT_TRUE(frameChanged(plainFrame, grabbed())) << "far away the folded roughness shows";
  document()->undoStack()->undo();
  EXPECT_FALSE(fold->isChecked());
}

// The Preview box and E switch the viewport to an engine's trace (a view option: no undo step),
// and the Engine Grid window draws Relief's exact trace and every engine with their errors.
TEST_F(ViewportControls, EnginePreviewAndTheEngineGrid) {
  m_window->resize(500, 400);
  document()->setParameter(ParamId::Tiling, 0.1);  // magnified: the grid's panels compare pixels
  const core::Image relief = grabbed();
  const int undoSteps = document()->undoStack()->count();
  auto* engines = m_window->findChild<QComboBox*>(QStringLiteral("enginePreview"));
  ASSERT_NE(engines, nullptr);
  ASSERT_EQ(engines->count(), 5);
  engines->setCurrentIndex(1);
  Q_EMIT engines->activated(1);
  EXPECT_EQ(viewDocument()->enginePreview(), core::Engine::Godot);
  EXPECT_EQ(viewport()->frameSettings().engine, core::Engine::Godot);
  EXPECT_TRUE(frameChanged(relief, grabbed()));
  EXPECT_EQ(document()->undoStack()->count(), undoSteps) << "a view option, not an edit";
  auto* next = m_window->findChild<QAction*>(QStringLiteral("nextEnginePreview"));
  ASSERT_NE(next, nullptr);
  EXPECT_EQ(next->shortcut(), QKeySequence(QStringLiteral("E")));
  next->trigger();
  EXPECT_EQ(viewDocument()->enginePreview(), core::Engine::Unreal);
  EXPECT_EQ(engines->currentIndex(), 2);
  for (int i = 0; i < 3; ++i)
    next->trigger();
  EXPECT_FALSE(viewDocument()->enginePreview().has_value()) << "E wraps round to Relief";
  EXPECT_EQ(engines->currentText(), QStringLiteral("Relief"));

  auto* gridAction = m_window->findChild<QAction*>(QStringLiteral("engineGridAction"));
  ASSERT_NE(gridAction, nullptr);
  gridAction->trigger();
  auto* grid = m_window->findChild<ui::EngineGridWindow*>(QStringLiteral("engineGrid"));
  ASSERT_NE(grid, nullptr);
  grid->waitForGrid();
  const QStringList lines = grid->summary().split(QLatin1Char('\n'));
  ASSERT_EQ(lines.size(), 5) << grid->summary().toStdString();
  EXPECT_TRUE(lines[0].startsWith(QStringLiteral("Relief exact: UV error: mean 0.0")))
      << lines[0].toStdString();
  EXPECT_TRUE(lines[1].startsWith(QStringLiteral("Godot 4: UV error: mean")))
      << lines[1].toStdString();
  const int panelWidth = viewport()->width() * int(viewport()->devicePixelRatioF());
  EXPECT_EQ(grid->picture().width(), 5 * std::min(panelWidth, 720) + 4 * 4);
  grid->close();
}

// View > Cost Table: every technique timed and measured at the view, the cheapest within the
// bound marked, and Apply puts its technique and samples on the material in one undo step.
TEST_F(ViewportControls, CostTableAppliesTheCheapestWithinTheBound) {
  m_window->resize(500, 400);
  document()->setParameter(ParamId::Tiling, 0.1);  // magnified: errors are measured
  grabbed();
  auto* action = m_window->findChild<QAction*>(QStringLiteral("costTableAction"));
  ASSERT_NE(action, nullptr);
  EXPECT_EQ(action->shortcut(), QKeySequence(QStringLiteral("Shift+K")));
  action->trigger();
  auto* window = m_window->findChild<ui::CostTableWindow*>(QStringLiteral("costTable"));
  ASSERT_NE(window, nullptr);
  window->waitForTable();
  const renderer::CostTable& table = window->table();
  ASSERT_EQ(table.rows.size(), 9u);
  EXPECT_EQ(window->tableWidget()->rowCount(), 9);
  window->errorBound()->setValue(0.5);
  const std::optional<std::size_t> cheapest = renderer::cheapestWithin(table, 0.5);
  ASSERT_TRUE(cheapest.has_value());
  EXPECT_TRUE(window->tableWidget()->item(int(*cheapest), 0)->font().bold());
  const core::Material& row = table.rows[*cheapest].material;
  const int steps = document()->undoStack()->count();
  window->applyChoice();
  EXPECT_EQ(document()->material().technique(), row.technique());
  EXPECT_EQ(document()->material().parameter(ParamId::MaxSamples),
            row.parameter(ParamId::MaxSamples));
  EXPECT_EQ(document()->material().parameter(ParamId::Tiling), 0.1) << "other settings kept";
  EXPECT_EQ(document()->undoStack()->count(), steps + 1);
  window->close();
}

TEST_F(ViewportControls, ErrorViewReportsTheErrorAgainstTheExactTrace) {
  m_window->resize(500, 400);
  // Tiled a tenth of a time, the map is magnified in this small viewport: pixels are compared.
  document()->setParameter(ParamId::Tiling, 0.1);
  QSignalSpy finished(viewport(), &ui::ViewportWidget::errorViewFinished);
  QComboBox* views = m_window->debugViewBox();
  const int error = views->findData(QStringLiteral("error"));
  views->setCurrentIndex(error);
  Q_EMIT views->activated(error);
  viewport()->update();
  ASSERT_TRUE(finished.wait(60000));
  ASSERT_TRUE(viewport()->errorMap().has_value());
  EXPECT_GT(viewport()->errorMap()->pixels, 1000);
  EXPECT_GE(viewport()->errorMap()->mean, 0.0);
  // The viewport shows the error map's colours. It once showed the colour map instead: Qt's
  // painter drew its image on the texture unit the renderer had left active and sampled unit 0.
  const core::Image frame = grabbed();
  const core::Image expected =
      core::colorizeErrorMap(*viewport()->errorMap(), core::kErrorDisplayTexels);
  ASSERT_EQ(frame.width(), expected.width());
  ASSERT_EQ(frame.height(), expected.height());
  int compared = 0, matching = 0;
  for (int y = frame.height() / 3; y < 2 * frame.height() / 3; y += 5) {
    for (int x = 0; x < frame.width(); x += 5) {
      if (expected.at(x, y, 3) < 1.0f)
        continue;  // not covered: the background shows
      ++compared;
      bool same = true;
      for (int c = 0; c < 3; ++c)
        same = same && std::abs(frame.at(x, y, c) - expected.at(x, y, c)) <= 2.0f / 255.0f;
      matching += same ? 1 : 0;
    }
  }
  EXPECT_GT(compared, 100);
  EXPECT_GT(matching, compared * 9 / 10) << matching << " of " << compared;
}

}  // namespace
}  // namespace relief::test
