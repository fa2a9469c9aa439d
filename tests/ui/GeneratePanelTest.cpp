// The Generate panel in the real window: a live preview and a full-size result in the
// background, Apply as one undo step that the viewport shows at once, undo restoring the old
// map, the material compensated when it must be, and clear messages for missing sources.
#include "core/image/ColorSpace.h"
#include "renderer/ImageConversion.h"
#include "support/ImageCompare.h"
#include "support/MainWindowFixture.h"
#include "support/TestPaths.h"
#include "ui/document/MaterialDocument.h"
#include "ui/panels/GeneratePanel.h"
#include "ui/panels/ParameterSlider.h"
#include "ui/tasks/GeneratorRunner.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/MainWindow.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

namespace relief::test {
namespace {

class GeneratePanelTest : public MainWindowFixture {
 protected:
  void SetUp() override { openWindow(1100, 700, samplePreset("bricks")); }
  ui::GeneratePanel* panel() { return m_window->generatePanel(); }

  bool waitForResult() {
    QSignalSpy ready(panel(), &ui::GeneratePanel::resultAvailable);
    return panel()->result().has_value() || ready.wait(60000);
  }
};

TEST_F(GeneratePanelTest, ApplyingANormalMapIsOneUndoStepTheViewportShows) {
  panel()->setGenerator(core::GeneratorKind::Normal);
  auto* strength = qobject_cast<ui::ParameterSlider*>(panel()->optionEditor("strength"));
  ASSERT_NE(strength, nullptr);
  strength->spinBox()->setValue(40.0);
  ASSERT_TRUE(waitForResult());
  ASSERT_TRUE(panel()->applyButton()->isEnabled());
  EXPECT_EQ(panel()->result()->image.width(), 1024);

  const auto before = document()->material().map(core::MapSlot::Normal).image;
  const core::Image frameBefore = grabbed();
  QTest::mouseClick(panel()->applyButton(), Qt::LeftButton);
  EXPECT_EQ(document()->undoStack()->count(), 1);
  EXPECT_NE(document()->material().map(core::MapSlot::Normal).image, before);
  EXPECT_GT(compareImages(frameBefore, grabbed()).maxError, 4.0 / 255.0);

  document()->undoStack()->undo();
  EXPECT_EQ(document()->material().map(core::MapSlot::Normal).image, before);
  EXPECT_EQ(compareImages(frameBefore, grabbed()).maxError, 0.0);
}

TEST_F(GeneratePanelTest, HeightFromNormalAlsoSetsTheHeightScaleInTheSameStep) {
  panel()->setGenerator(core::GeneratorKind::Height);
  ASSERT_TRUE(waitForResult());
  ASSERT_TRUE(panel()->result()->depthTexels.has_value());
  const double scale = document()->material().parameter(core::ParamId::HeightScale);
  QTest::mouseClick(panel()->applyButton(), Qt::LeftButton);
  EXPECT_EQ(document()->undoStack()->count(), 1);
  const double expected = *panel()->result()->depthTexels / 1024.0;
  EXPECT_NEAR(document()->material().parameter(core::ParamId::HeightScale), expected, 1e-3);
  EXPECT_NEAR(document()->material().parameter(core::ParamId::HeightBias), -expected, 1e-3);
  document()->undoStack()->undo();
  EXPECT_EQ(document()->material().parameter(core::ParamId::HeightScale), scale);
}

TEST_F(GeneratePanelTest, PackingKeepsTheReliefAndSwitchesToAlphaHeight) {
  panel()->setGenerator(core::GeneratorKind::Pack);
  ASSERT_TRUE(waitForResult());
  ASSERT_TRUE(panel()->result()->levels.has_value());
  QTest::mouseClick(panel()->applyButton(), Qt::LeftButton);
  const core::Material& material = document()->material();
  EXPECT_TRUE(material.parameterFlag(core::ParamId::HeightInNormalAlpha));
  EXPECT_EQ(material.image(core::MapSlot::Normal)->channels(), 4);
  // Same relief: the bricks' heights spanned levels->low..high at scale 0.03, bias -0.03.
  const core::LevelsRange range = *panel()->result()->levels;
  EXPECT_NEAR(material.parameter(core::ParamId::HeightScale), 0.03 * (range.high - range.low),
              1e-6);
}

// Pack's engine layouts from whatever maps the material has: the bricks sample has no AO or
// roughness map, so its ORM is the neutral occlusion 1, roughness 1 and metallic 0 everywhere;
// the result is saved, not applied (no slot holds an ORM map), and the status says why.
TEST_F(GeneratePanelTest, PackingAnOrmMapUsesNeutralValuesAndIsSavedNotApplied) {
  panel()->setGenerator(core::GeneratorKind::Pack);
  auto* layout = qobject_cast<QComboBox*>(panel()->optionEditor("layout"));
  ASSERT_NE(layout, nullptr);
  layout->setCurrentIndex(1);
  ASSERT_EQ(layout->currentText(), QStringLiteral("orm"));
  Q_EMIT layout->activated(1);
  ASSERT_TRUE(waitForResult());
  const core::Image& orm = panel()->result()->image;
  ASSERT_EQ(orm.channels(), 3);
  EXPECT_EQ(orm.width(), 1024);
  for (int y : {0, 511, 1023}) {
    EXPECT_FLOAT_EQ(orm.at(y, y, 0), 1.0f);
    EXPECT_FLOAT_EQ(orm.at(y, y, 1), 1.0f);
    EXPECT_FLOAT_EQ(orm.at(y, y, 2), 0.0f);
  }
  EXPECT_FALSE(panel()->applyButton()->isEnabled());
  EXPECT_TRUE(panel()->saveButton()->isEnabled());
  bool explained = false;
  for (const QLabel* label : panel()->findChildren<QLabel*>())
    explained = explained || label->text().contains(QStringLiteral("no ao map"));
  EXPECT_TRUE(explained);
}

TEST_F(GeneratePanelTest, AMissingSourceMapIsExplained) {
  document()->clearMap(core::MapSlot::Height);
  panel()->setGenerator(core::GeneratorKind::AmbientOcclusion);
  EXPECT_FALSE(panel()->applyButton()->isEnabled());
  const QList<QLabel*> labels = panel()->findChildren<QLabel*>();
  bool explained = false;
  for (const QLabel* label : labels)
    explained = explained || label->text().contains(QStringLiteral("no height map"));
  EXPECT_TRUE(explained);
}

TEST_F(GeneratePanelTest, EditsWhileRunningCancelTheOldWork) {
  panel()->setGenerator(core::GeneratorKind::AmbientOcclusion);
  auto* radius = qobject_cast<ui::ParameterSlider*>(panel()->optionEditor("radius"));
  ASSERT_NE(radius, nullptr);
  // Several quick edits, as while dragging: only the last one's result arrives.
  for (double value : {10.0, 12.0, 14.0, 6.0})
    radius->spinBox()->setValue(value);
  ASSERT_TRUE(waitForResult());
  QTest::qWait(200);
  EXPECT_FALSE(panel()->runner()->isRunning());
  EXPECT_TRUE(panel()->applyButton()->isEnabled());
}

}  // namespace
}  // namespace relief::test
