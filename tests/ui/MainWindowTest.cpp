// The real main window under Xvfb: it opens on a sample, the viewport shows a lit frame, the
// parameter sliders change it live, undo brings it back, and the viewport shows exactly what
// the offscreen renderer (and so relief-cli render) produces for the same view.
#include "core/image/ColorSpace.h"
#include "core/image/ImageIO.h"
#include "core/preset/MaterialPreset.h"
#include "renderer/ImageConversion.h"
#include "renderer/OffscreenRenderer.h"
#include "support/DialogAnswerer.h"
#include "support/ImageCompare.h"
#include "support/MainWindowFixture.h"
#include "support/TestPaths.h"
#include "ui/document/MaterialDocument.h"
#include "ui/panels/LightPanel.h"
#include "ui/panels/ParameterPanel.h"
#include "ui/panels/ParameterSlider.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/MainWindow.h"

#include <QAction>
#include <QCheckBox>
#include <QFileDialog>
#include <QInputDialog>
#include <QLabel>
#include <QSlider>
#include <QStatusBar>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

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

// The status bar leaves room for messages (the GPU's name alone, its whole description in the
// tooltip), and a message about one material does not stay when another is opened.
TEST_F(MainWindowTest, StatusBarMessagesHaveRoomAndGoWithTheirMaterial) {
  const QList<QLabel*> labels = m_window->statusBar()->findChildren<QLabel*>();
  const auto gpu = std::find_if(labels.begin(), labels.end(), [](const QLabel* label) {
    return label->toolTip().contains(QStringLiteral("OpenGL"));
  });
  ASSERT_NE(gpu, labels.end()) << "no label carries the renderer's description";
  EXPECT_FALSE((*gpu)->text().contains(QStringLiteral("OpenGL"))) << (*gpu)->text().toStdString();
  EXPECT_FALSE((*gpu)->text().isEmpty());
  m_window->statusBar()->showMessage(QStringLiteral("about the bricks"));
  document()->reset(core::Material{}, QString());
  EXPECT_TRUE(m_window->statusBar()->currentMessage().isEmpty());
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
  offscreen.value()->setMesh(m_window->viewDocument()->mesh());
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
  // A set dropped together is one undo step.
  EXPECT_EQ(m_window->document()->undoStack()->count(), 1);
  EXPECT_TRUE(m_window->windowTitle().contains(QLatin1Char('*')));
  m_window->document()->undoStack()->undo();
  EXPECT_NE(QString::fromStdString(material.map(core::MapSlot::Normal).sourcePath), normal);
  EXPECT_NE(QString::fromStdString(material.map(core::MapSlot::Height).sourcePath), height);
}

// File > Open Map takes several files at once, as game data names them (_d, _n, _z), and a file
// whose name says nothing but whose texels are a normal map's goes to the normal slot without a
// question: one undo step for the set, and a status message naming each file's slot.
TEST_F(MainWindowTest, OpenMapTakesASetNamedAsGameDataAndTellsNormalMapsByTheirTexels) {
  const std::string folder = scratchFolder() + "/ui-game-set";
  std::filesystem::create_directories(folder);
  const auto copy = [&](const char* from, const char* to) {
    std::filesystem::copy_file(sourcePath(from), folder + "/" + to,
                               std::filesystem::copy_options::overwrite_existing);
    return QString::fromStdString(folder + "/" + to);
  };
  const QString colour = copy("samples/tiles/tiles_color.png", "floor_d.png");
  const QString height = copy("samples/tiles/tiles_height.png", "floor_z.png");
  const QString mystery = copy("samples/tiles/tiles_normal.png", "scan0042.png");
  ui::MaterialDocument* document = m_window->document();
  const int stepsBefore = document->undoStack()->count();

  int questions = 0;  // a "Which map is this?" question would be a failure: answer and count it
  QTimer guard;
  QObject::connect(&guard, &QTimer::timeout, [&] {
    if (auto* input = qobject_cast<QInputDialog*>(QApplication::activeModalWidget())) {
      ++questions;
      input->reject();
    }
  });
  guard.start(50);
  QTimer::singleShot(200, [&] {
    auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
    ASSERT_NE(dialog, nullptr);
    EXPECT_EQ(dialog->fileMode(), QFileDialog::ExistingFiles);
    dialog->setDirectory(QString::fromStdString(folder));
    dialog->selectFile(QStringLiteral("\"floor_d.png\" \"floor_z.png\" \"scan0042.png\""));
    QMetaObject::invokeMethod(dialog, "accept");  // accept() is a protected slot
  });
  QAction* openMap = nullptr;
  for (QAction* action : m_window->findChildren<QAction*>()) {
    if (action->shortcut() == QKeySequence(QStringLiteral("Ctrl+Shift+O")))
      openMap = action;
  }
  ASSERT_NE(openMap, nullptr);
  openMap->trigger();
  guard.stop();

  const core::Material& material = document->material();
  EXPECT_EQ(QString::fromStdString(material.map(core::MapSlot::Color).sourcePath), colour);
  EXPECT_EQ(QString::fromStdString(material.map(core::MapSlot::Height).sourcePath), height);
  EXPECT_EQ(QString::fromStdString(material.map(core::MapSlot::Normal).sourcePath), mystery);
  EXPECT_EQ(questions, 0);
  EXPECT_EQ(document->undoStack()->count(), stepsBefore + 1);
  const QString status = m_window->statusBar()->currentMessage();
  EXPECT_TRUE(status.contains(QStringLiteral("scan0042.png as the normal map")))
      << status.toStdString();
  EXPECT_TRUE(status.contains(QStringLiteral("floor_z.png as the height map")))
      << status.toStdString();
}

// An ORM texture (R occlusion, G roughness, B metallic) from the maps panel's "Load ORM…"
// button fills three slots in one undo step, each remembering its channel, which the panel
// shows; a grey file is refused with a message naming it and nothing changes. A file named
// *_orm opened as a map takes the same way.
TEST_F(MainWindowTest, AnOrmTextureFillsThreeSlotsInOneUndoStep) {
  const std::string folder = scratchFolder() + "/ui-orm";
  std::filesystem::create_directories(folder);
  core::Image orm(16, 16, 3);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      orm.at(x, y, 0) = float(x) / 15.0f;
      orm.at(x, y, 1) = float(y) / 15.0f;
      orm.at(x, y, 2) = 1.0f;
    }
  }
  const QString path = QString::fromStdString(folder + "/stone_orm.png");
  ASSERT_TRUE(core::saveImage(orm, path.toStdString(), core::SampleFormat::UInt8).ok());
  ui::MaterialDocument* document = m_window->document();
  const int stepsBefore = document->undoStack()->count();

  // The button opens a file dialog; answer it with the file.
  QTimer::singleShot(200, [&] {
    auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
    ASSERT_NE(dialog, nullptr);
    dialog->selectFile(path);
    QMetaObject::invokeMethod(dialog, "accept");  // accept() is a protected slot
  });
  auto* button = m_window->findChild<QToolButton*>(QStringLiteral("load_orm"));
  ASSERT_NE(button, nullptr);
  button->click();
  const core::MapSlot slots[] = {core::MapSlot::AmbientOcclusion, core::MapSlot::Roughness,
                                 core::MapSlot::Metallic};
  for (int c = 0; c < 3; ++c) {
    const core::MaterialMap& map = document->material().map(slots[c]);
    ASSERT_TRUE(map.image) << c;
    EXPECT_EQ(QString::fromStdString(map.sourcePath), path);
    EXPECT_EQ(map.sourceChannel, c);
    EXPECT_NEAR(map.image->at(15, 0, 0), orm.at(15, 0, c), 1e-6) << c;
    EXPECT_NEAR(map.image->at(0, 15, 0), orm.at(0, 15, c), 1e-6) << c;
  }
  EXPECT_EQ(document->undoStack()->count(), stepsBefore + 1);
  bool shown = false;
  for (const QLabel* label : m_window->findChildren<QLabel*>())
    shown = shown || label->text().contains(QStringLiteral("stone_orm.png (channel G)"));
  EXPECT_TRUE(shown) << "the maps panel names the roughness map's channel";

  document->undoStack()->undo();
  for (core::MapSlot slot : slots)
    EXPECT_FALSE(document->material().hasMap(slot)) << core::mapSlotName(slot);

  // A grey *_orm file: refused, named, nothing changes.
  const QString grey = QString::fromStdString(folder + "/grey_orm.png");
  ASSERT_TRUE(
      core::saveImage(core::Image(8, 8, 1), grey.toStdString(), core::SampleFormat::UInt8).ok());
  const int stepsNow = document->undoStack()->index();
  {
    DialogAnswerer ok(QStringLiteral("OK"));
    m_window->openFiles({grey});
    EXPECT_EQ(ok.answered(), 1);
    EXPECT_TRUE(ok.lastText().contains(QStringLiteral("grey_orm.png")))
        << ok.lastText().toStdString();
  }
  EXPECT_EQ(document->undoStack()->index(), stepsNow);
  EXPECT_FALSE(document->material().hasMap(core::MapSlot::Roughness));
  // Opened by name, the good file splits as from the button.
  m_window->openFiles({path});
  EXPECT_EQ(document->material().map(core::MapSlot::Metallic).sourceChannel, 2);
  EXPECT_EQ(document->undoStack()->index(), stepsNow + 1);
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

// A light drag in the viewport is one undo step of the view document, and the Light panel, which
// knows only the document, shows it; undo brings both back.
TEST_F(MainWindowTest, ALightDragIsOneUndoStepThatThePanelFollows) {
  ui::ViewportWidget* viewport = m_window->viewport();
  QUndoStack* stack = m_window->document()->undoStack();
  const int steps = stack->index();
  const core::DirectionalLight before = m_window->viewDocument()->light();
  const QPoint centre = viewport->rect().center();
  QTest::mousePress(viewport, Qt::LeftButton, Qt::ControlModifier, centre);
  for (int x = 10; x <= 60; x += 10)
    QTest::mouseMove(viewport, centre + QPoint(x, -x / 2));
  QTest::mouseRelease(viewport, Qt::LeftButton, Qt::ControlModifier, centre + QPoint(60, -30));
  const core::DirectionalLight dragged = m_window->viewDocument()->light();
  EXPECT_NE(dragged, before);
  EXPECT_EQ(stack->index(), steps + 1) << "six moves, one step";
  EXPECT_EQ(viewport->view().light, dragged);
  EXPECT_EQ(m_window->lightPanel()->azimuthControl()->value(),
            double((int(std::lround(dragged.azimuthDeg)) % 360 + 360) % 360));
  EXPECT_TRUE(m_window->windowTitle().contains(QLatin1Char('*'))) << "the preset saves it";
  stack->undo();
  EXPECT_EQ(m_window->viewDocument()->light(), before);
  EXPECT_EQ(viewport->view().light, before);
  EXPECT_EQ(m_window->lightPanel()->azimuthControl()->value(),
            double(std::lround(before.azimuthDeg)));
}

}  // namespace
}  // namespace relief::test
