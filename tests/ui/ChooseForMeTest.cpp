// Choose for Me in the real window (ui/compare/ChooseForMeDialog.h), on a 128x128 cut of the
// cobblestones: the run happens in relief-cli while the editor's event loop keeps turning, the
// table lists every candidate with one chosen per map, Apply writes exactly the formats the
// CLI's report chose into the document as one undo step and compresses them into the 3D wipe,
// Compare All Formats marks the chosen format's row, and a budget below what the maps can
// ship at says so in the dialog without changing the material. And the panel's RDO slider: one
// trade written into every map whose format has RDO as one undo step, Zstandard turned on, and
// the maps compressed again, smaller on disk.
#include "support/CroppedSample.h"
#include "support/MainWindowFixture.h"
#include "support/TestPaths.h"
#include "ui/compare/ChooseForMeDialog.h"
#include "ui/compare/CompareAllDialog.h"
#include "ui/document/MaterialDocument.h"
#include "ui/document/ViewDocument.h"
#include "ui/panels/CompressPanel.h"
#include "ui/window/MainWindow.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QTableWidget>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <map>

namespace relief::test {
namespace {

using core::MapSlot;

class ChooseForMeTest : public MainWindowFixture {
 protected:
  void SetUp() override {
    openWindow(1200, 760, croppedSamplePreset("cobblestones", 128, scratchFolder() + "/cut"));
  }
  ui::CompressPanel* panel() { return m_window->compressPanel(); }
  ui::ChooseForMeDialog* dialog() {
    ui::ChooseForMeDialog* chooser = panel()->chooseForMeDialog();
    chooser->setCliPath(QStringLiteral(RELIEF_CLI_PATH));
    chooser->setViewSize(QSize(128, 96));  // what the test checks does not depend on the size
    return chooser;
  }
  // Runs the dialog's choice to its end; returns how often a 10 ms timer ticked meanwhile.
  int runChoice() {
    int ticks = 0;
    QTimer heartbeat;
    QObject::connect(&heartbeat, &QTimer::timeout, [&ticks] { ++ticks; });
    heartbeat.start(10);
    QTest::mouseClick(dialog()->chooseButton(), Qt::LeftButton);
    EXPECT_TRUE(dialog()->running());
    for (int waited = 0; dialog()->running() && waited < 300000; waited += 50)
      QTest::qWait(50);
    EXPECT_FALSE(dialog()->running());
    return ticks;
  }
};

TEST_F(ChooseForMeTest, TheChoiceReachesTheDocumentAndTheWipe) {
  QTest::mouseClick(panel()->chooseForMeButton(), Qt::LeftButton);
  ASSERT_TRUE(dialog()->isVisible());
  dialog()->goalBox()->setCurrentIndex(0);  // budget
  dialog()->valueBox()->setValue(100.0);    // MB: everything fits
  EXPECT_GT(runChoice(), 20) << "the editor kept turning while relief-cli worked";
  ASSERT_FALSE(dialog()->chosen().empty()) << dialog()->summary()->text().toStdString();
  EXPECT_TRUE(dialog()->summary()->text().contains(QStringLiteral("Chosen")))
      << dialog()->summary()->text().toStdString();
  // Desktop candidates: colour BC1 | BC7, normal BC1 | BC5 | BC7, height BC4, each without
  // RDO and with RDO 16.
  EXPECT_EQ(dialog()->table()->rowCount(), 12);
  EXPECT_EQ(dialog()->chosen().size(), 3u);
  ASSERT_TRUE(dialog()->applyButton()->isEnabled());

  const int steps = document()->undoStack()->count();
  QTest::mouseClick(dialog()->applyButton(), Qt::LeftButton);
  EXPECT_EQ(document()->undoStack()->count(), steps + 1) << "one undo step";
  for (const auto& [slot, choice] : dialog()->chosen()) {
    ASSERT_TRUE(document()->compression(slot).has_value());
    EXPECT_EQ(document()->compression(slot)->format, choice.format);
    EXPECT_EQ(document()->compression(slot)->rdoLambda, choice.rdoLambda);
    EXPECT_TRUE(document()->compression(slot)->mipmaps);
  }
  // The panel compresses them and shows the wipe.
  for (int waited = 0; panel()->outcomes().size() < 3 && waited < 120000; waited += 50)
    QTest::qWait(50);
  ASSERT_EQ(panel()->outcomes().size(), 3u);
  for (const auto& [slot, choice] : dialog()->chosen()) {
    EXPECT_EQ(panel()->outcomes().at(slot).job.settings.format, choice.format);
    EXPECT_EQ(panel()->outcomes().at(slot).job.settings.rdoLambda, choice.rdoLambda);
  }
  EXPECT_EQ(viewDocument()->compressedView(), ui::ViewDocument::CompressedView::Wipe);

  // Compare All Formats marks the material's choice in the colour map's table.
  panel()->resultsTable()->selectRow(0);
  panel()->openCompareAll();
  ui::CompareAllDialog* all = panel()->compareAllDialog();
  for (int waited = 0; all->runner()->isRunning() && waited < 120000; waited += 50)
    QTest::qWait(50);
  int marked = 0;
  QStringList rows;
  for (int row = 0; row < all->table()->rowCount(); ++row) {
    rows << all->table()->item(row, 0)->text();
    marked += all->table()->item(row, 0)->text().contains(QStringLiteral("Choose for Me")) ? 1 : 0;
  }
  EXPECT_EQ(marked, 1) << rows.join(QStringLiteral(" | ")).toStdString();
  all->close();

  // Undo puts the earlier choices back in one step.
  document()->undoStack()->undo();
  for (const auto& [slot, choice] : dialog()->chosen())
    EXPECT_FALSE(document()->compression(slot).has_value());
}

// Compare All Formats renders the material with each row's map in place of the original (in
// relief-cli, as Choose for Me) and fills the Rendered FLIP column: every row a value, more for
// ASTC 8x8 (2 bits a texel) than for 4x4 (8 bits), while the editor keeps turning.
TEST_F(ChooseForMeTest, CompareAllRendersEachFormatInTheMaterial) {
  ui::CompareAllDialog* all = panel()->compareAllDialog();
  all->setCliPath(QStringLiteral(RELIEF_CLI_PATH));
  all->setViewSize(QSize(64, 48));
  panel()->openCompareAll();  // the colour map, the first with a map
  int ticks = 0;
  QTimer heartbeat;
  QObject::connect(&heartbeat, &QTimer::timeout, [&ticks] { ++ticks; });
  heartbeat.start(10);
  for (int waited = 0; (all->runner()->isRunning() || all->rendering()) && waited < 240000;
       waited += 50)
    QTest::qWait(50);
  ASSERT_FALSE(all->rendering());
  EXPECT_GT(ticks, 20);
  int renderedColumn = -1;
  for (int c = 0; c < all->table()->columnCount(); ++c) {
    if (all->table()->horizontalHeaderItem(c)->text() == QStringLiteral("Rendered FLIP"))
      renderedColumn = c;
  }
  ASSERT_GE(renderedColumn, 0);
  ASSERT_GT(all->table()->rowCount(), 5);
  std::map<int, double> flips;  // by format
  for (int row = 0; row < all->table()->rowCount(); ++row) {
    const QTableWidgetItem* item = all->table()->item(row, renderedColumn);
    ASSERT_NE(item, nullptr) << all->table()->item(row, 0)->text().toStdString();
    const double flip = item->data(Qt::UserRole).toDouble();
    EXPECT_GT(flip, 0.0) << row;
    EXPECT_LT(flip, 0.2) << row;
    flips[all->table()->item(row, 0)->data(Qt::UserRole).toInt()] = flip;
  }
  ASSERT_TRUE(flips.count(int(core::TextureFormat::Astc8x8)) &&
              flips.count(int(core::TextureFormat::Astc4x4)));
  EXPECT_GT(flips[int(core::TextureFormat::Astc8x8)], flips[int(core::TextureFormat::Astc4x4)]);
  all->close();
}

TEST_F(ChooseForMeTest, ABudgetTooSmallIsSaidAndChangesNothing) {
  QTest::mouseClick(panel()->chooseForMeButton(), Qt::LeftButton);
  dialog()->goalBox()->setCurrentIndex(0);
  dialog()->valueBox()->setValue(0.01);  // 10 kB: less than three 128x128 maps ever take
  runChoice();
  EXPECT_TRUE(dialog()->chosen().empty());
  EXPECT_FALSE(dialog()->applyButton()->isEnabled());
  EXPECT_TRUE(dialog()->summary()->text().contains(QStringLiteral("cannot be met")))
      << dialog()->summary()->text().toStdString();
  for (MapSlot slot : core::kAllMapSlots)
    EXPECT_FALSE(document()->compression(slot).has_value());
}

TEST_F(ChooseForMeTest, TheRdoSliderShrinksWhatShips) {
  // BC1 colour, EAC R11 height (no RDO), compressed once without a trade.
  for (const auto& [slot, format] : {std::pair{MapSlot::Color, core::TextureFormat::Bc1},
                                     std::pair{MapSlot::Height, core::TextureFormat::EacR11}}) {
    QComboBox* box = panel()->formatBox(slot);
    box->setCurrentIndex(box->findData(int(format)));
  }
  panel()->compress();
  for (int waited = 0; panel()->outcomes().size() < 2 && waited < 60000; waited += 50)
    QTest::qWait(50);
  ASSERT_EQ(panel()->outcomes().size(), 2u);
  const std::uint64_t before = panel()->outcomes().at(MapSlot::Color).report.size->ktx2Bytes;

  const int steps = document()->undoStack()->count();
  QSlider* slider = panel()->rdoSlider();
  slider->setValue(ui::CompressPanel::rdoStep(16.0));  // as a key press or a click sets it
  EXPECT_EQ(document()->undoStack()->count(), steps + 1) << "one undo step";
  EXPECT_EQ(document()->compression(MapSlot::Color)->rdoLambda, 16.0f);
  EXPECT_EQ(document()->compression(MapSlot::Height)->rdoLambda, 0.0f) << "EAC has no RDO";
  // The panel compresses again (Zstandard on, since RDO pays after it): smaller on disk.
  for (int waited = 0;
       waited < 60000 && panel()->outcomes().at(MapSlot::Color).job.settings.rdoLambda != 16.0f;
       waited += 50)
    QTest::qWait(50);
  const core::CompressionOutcome& traded = panel()->outcomes().at(MapSlot::Color);
  ASSERT_EQ(traded.job.settings.rdoLambda, 16.0f);
  EXPECT_GT(traded.report.size->zstdLevel, 0);
  EXPECT_LT(traded.report.size->ktx2Bytes, before);
  document()->undoStack()->undo();
  EXPECT_EQ(document()->compression(MapSlot::Color)->rdoLambda, 0.0f);
  EXPECT_EQ(slider->value(), 0) << "the slider follows the document";
}

}  // namespace
}  // namespace relief::test
