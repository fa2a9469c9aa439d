// The real main window under Xvfb: it opens on a sample, the viewport shows a lit frame, the
// parameter sliders change it live, undo brings it back, and the viewport shows exactly what
// the offscreen renderer (and so relief-cli render) produces for the same view.
#include "core/image/ColorSpace.h"
#include "core/material/MaterialPreset.h"
#include "renderer/ImageConversion.h"
#include "renderer/OffscreenRenderer.h"
#include "support/ImageCompare.h"
#include "support/MainWindowFixture.h"
#include "support/TestPaths.h"
#include "ui/document/MaterialDocument.h"
#include "ui/panels/ParameterPanel.h"
#include "ui/panels/ParameterSlider.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/MainWindow.h"

#include <QCheckBox>
#include <QLabel>
#include <QSlider>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

namespace relief::test {
namespace {

// The frame changed visibly: on average over the whole frame (background included, which no
// parameter touches) and strongly somewhere.
void expectVisibleChange(const core::Image& before, const core::Image& after) {
  const ImageDifference change = compareImages(before, after);
  EXPECT_GT(change.meanError, 0.3 / 255.0);
  EXPECT_GT(change.maxError, 16.0 / 255.0);
}

class MainWindowTest : public MainWindowFixture {
 protected:
  void SetUp() override { openWindow(1000, 700, samplePreset("bricks")); }
};

TEST_F(MainWindowTest, ShowsALitNormalMappedSample) {
  const core::Image frame = grabbed();
  ASSERT_GT(frame.width(), 100);
  // Not empty: the centre (the material) is brighter than a background corner and coloured
  // like brick (more red than blue).
  const float* centre = frame.pixel(frame.width() / 2, frame.height() / 2);
  const float* corner = frame.pixel(2, 2);
  EXPECT_GT(centre[0], corner[0] + 0.1f);
  EXPECT_GT(centre[0], centre[2] + 0.05f);
  EXPECT_TRUE(m_window->windowTitle().startsWith(QStringLiteral("bricks")))
      << m_window->windowTitle().toStdString();
}

TEST_F(MainWindowTest, MovingASliderChangesTheFrameAndUndoRestoresIt) {
  const core::Image before = grabbed();
  auto* tiling =
      qobject_cast<ui::ParameterSlider*>(m_window->parameterPanel()->editor(core::ParamId::Tiling));
  ASSERT_NE(tiling, nullptr);

  // Drag the slider handle as a user would: press on the handle, move in steps, release.
  QSlider* slider = tiling->slider();
  const QPoint handle = sliderHandle(slider);
  QTest::mousePress(slider, Qt::LeftButton, {}, handle);
  for (int step = 1; step <= 5; ++step) {
    QTest::mouseMove(slider, handle + QPoint(step * slider->width() / 12, 0));
  }
  QTest::mouseRelease(slider, Qt::LeftButton, {}, handle + QPoint(5 * slider->width() / 12, 0));
  const double dragged = m_window->document()->material().parameter(core::ParamId::Tiling);
  EXPECT_GT(dragged, 2.5);

  expectVisibleChange(before, grabbed());

  // The whole drag is one undo step.
  QUndoStack* undo = m_window->document()->undoStack();
  EXPECT_EQ(undo->count(), 1);
  undo->undo();
  EXPECT_EQ(m_window->document()->material().parameter(core::ParamId::Tiling), 2.0);
  EXPECT_EQ(tiling->value(), 2.0);
  EXPECT_EQ(compareImages(before, grabbed()).maxError, 0.0);
  undo->redo();
  EXPECT_EQ(m_window->document()->material().parameter(core::ParamId::Tiling), dragged);
}

// The status bar's samples per pixel follows the view once it rests: a layered march of n
// layers takes 1 to n + 1 height samples a pixel (parallax.glsl).
TEST_F(MainWindowTest, StatusBarShowsHeightSamplesPerPixelOnceTheViewRests) {
  auto* label = m_window->findChild<QLabel*>(QStringLiteral("samplesPerPixel"));
  ASSERT_NE(label, nullptr);
  document()->setParameter(core::ParamId::ShadowMode, double(core::ShadowMode::Off));
  document()->setParameter(core::ParamId::MinSamples, 4.0);
  document()->setParameter(core::ParamId::MaxSamples, 4.0);
  const auto shownMean = [&] { return label->text().section(QLatin1Char(' '), 0, 0).toDouble(); };
  label->clear();
  QTRY_VERIFY_WITH_TIMEOUT(!label->text().isEmpty(), 10000);
  EXPECT_GE(shownMean(), 1.0);
  EXPECT_LE(shownMean(), 5.0);
  // More layers, more samples: the label follows the change.
  document()->setParameter(core::ParamId::MinSamples, 32.0);
  document()->setParameter(core::ParamId::MaxSamples, 32.0);
  const double before = shownMean();
  QTRY_VERIFY_WITH_TIMEOUT(shownMean() > before + 1.0, 10000);
  EXPECT_LE(shownMean(), 33.0);
}

TEST_F(MainWindowTest, CheckBoxParameterChangesTheFrame) {
  const core::Image before = grabbed();
  auto* yDown =
      qobject_cast<QCheckBox*>(m_window->parameterPanel()->editor(core::ParamId::NormalYDown));
  ASSERT_NE(yDown, nullptr);
  QTest::mouseClick(yDown, Qt::LeftButton);
  EXPECT_EQ(m_window->document()->material().parameter(core::ParamId::NormalYDown), 1.0);
  expectVisibleChange(before, grabbed());
}

TEST_F(MainWindowTest, ViewportMatchesTheOffscreenRenderOfTheSameView) {
  // relief-cli render uses the offscreen renderer: the viewport must show the same pixels.
  const core::Image viewportFrame = grabbed();
  auto offscreen = renderer::OffscreenRenderer::create();
  ASSERT_TRUE(offscreen.ok()) << offscreen.error();
  offscreen.value()->setMesh(m_window->viewport()->mesh());
  offscreen.value()->setMaterial(m_window->document()->material());
  core::Result<core::Image> rendered = offscreen.value()->render(
      m_window->viewport()->view(), viewportFrame.width(), viewportFrame.height());
  ASSERT_TRUE(rendered.ok()) << rendered.error();
  const ImageDifference difference = compareImages(viewportFrame, rendered.value());
  EXPECT_TRUE(difference.sameShape);
  EXPECT_LE(difference.maxError, 1.0 / 255.0);
}

TEST_F(MainWindowTest, DroppedFilesGoToTheSlotTheirNamesHint) {
  const QString normal = QString::fromStdString(sourcePath("samples/tiles/tiles_normal.png"));
  const QString height = QString::fromStdString(sourcePath("samples/tiles/tiles_height.png"));
  m_window->openFiles({normal, height});
  const core::Material& material = m_window->document()->material();
  EXPECT_EQ(QString::fromStdString(material.map(core::MapSlot::Normal).sourcePath), normal);
  EXPECT_EQ(QString::fromStdString(material.map(core::MapSlot::Height).sourcePath), height);
  // Each map replacement is its own undo step.
  EXPECT_EQ(m_window->document()->undoStack()->count(), 2);
  EXPECT_TRUE(m_window->windowTitle().contains(QLatin1Char('*')));
}

TEST_F(MainWindowTest, CtrlDragMovesTheLightAndPlainDragOrbits) {
  ui::ViewportWidget* viewport = m_window->viewport();
  const float azimuth = viewport->view().light.azimuthDeg;
  const float yaw = viewport->view().camera.yawDeg;
  const QPoint centre = viewport->rect().center();
  QTest::mousePress(viewport, Qt::LeftButton, Qt::ControlModifier, centre);
  QTest::mouseMove(viewport, centre + QPoint(50, 0));
  QTest::mouseRelease(viewport, Qt::LeftButton, Qt::ControlModifier, centre + QPoint(50, 0));
  EXPECT_NE(viewport->view().light.azimuthDeg, azimuth);
  EXPECT_EQ(viewport->view().camera.yawDeg, yaw);

  QTest::mousePress(viewport, Qt::LeftButton, {}, centre);
  QTest::mouseMove(viewport, centre + QPoint(50, 0));
  QTest::mouseRelease(viewport, Qt::LeftButton, {}, centre + QPoint(50, 0));
  EXPECT_NE(viewport->view().camera.yawDeg, yaw);
}

}  // namespace
}  // namespace relief::test
