// Choose for Me in the real window (ui/compare/ChooseForMeDialog.h), on a 128x128 cut of the
// cobblestones: the run happens in relief-cli while the editor's event loop keeps turning, the
// table lists every candidate with one chosen per map, Apply writes exactly the formats the
// CLI's report chose into the document as one undo step and compresses them into the 3D wipe,
// Compare All Formats marks the chosen format's row, and a budget below what the maps can
// ship at says so in the dialog without changing the material.
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
#include <QTableWidget>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <gtest/gtest.h>

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
  // Desktop candidates: colour BC1 | BC7, normal BC1 | BC5 | BC7, height BC4.
  EXPECT_EQ(dialog()->table()->rowCount(), 6);
  EXPECT_EQ(dialog()->chosen().size(), 3u);
  ASSERT_TRUE(dialog()->applyButton()->isEnabled());

  const int steps = document()->undoStack()->count();
  QTest::mouseClick(dialog()->applyButton(), Qt::LeftButton);
  EXPECT_EQ(document()->undoStack()->count(), steps + 1) << "one undo step";
  for (const auto& [slot, format] : dialog()->chosen()) {
    ASSERT_TRUE(document()->compression(slot).has_value());
    EXPECT_EQ(document()->compression(slot)->format, format);
    EXPECT_TRUE(document()->compression(slot)->mipmaps);
  }
  // The panel compresses them and shows the wipe.
  for (int waited = 0; panel()->outcomes().size() < 3 && waited < 120000; waited += 50)
    QTest::qWait(50);
  ASSERT_EQ(panel()->outcomes().size(), 3u);
  for (const auto& [slot, format] : dialog()->chosen())
    EXPECT_EQ(panel()->outcomes().at(slot).job.settings.format, format);
  EXPECT_EQ(viewDocument()->compressedView(), ui::ViewDocument::CompressedView::Wipe);

  // Compare All Formats marks the material's choice in the colour map's table.
  panel()->resultsTable()->selectRow(0);
  panel()->openCompareAll();
  ui::CompareAllDialog* all = panel()->compareAllDialog();
  for (int waited = 0; all->runner()->isRunning() && waited < 120000; waited += 50)
    QTest::qWait(50);
  int marked = 0;
  for (int row = 0; row < all->table()->rowCount(); ++row)
    marked += all->table()->item(row, 0)->text().contains(QStringLiteral("Choose for Me")) ? 1 : 0;
  EXPECT_EQ(marked, 1);
  all->close();

  // Undo puts the earlier choices back in one step.
  document()->undoStack()->undo();
  for (const auto& [slot, format] : dialog()->chosen())
    EXPECT_FALSE(document()->compression(slot).has_value());
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

}  // namespace
}  // namespace relief::test
