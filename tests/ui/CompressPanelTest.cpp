// The Compress panel in the real window: compression runs in the background (the event loop
// keeps turning), the results are listed, the viewport renders the compressed blocks (natively
// on this driver, as the status bar says) in a wipe against the original, Cancel leaves the
// material and the earlier results as they were, the 2D compare view is texel-exact when
// zoomed, and "compare all formats" fills its table and chart and hands a format back.
#include "core/compression/BlockRdo.h"
#include "support/MainWindowFixture.h"
#include "support/TestPaths.h"
#include "ui/compare/CompareAllDialog.h"
#include "ui/compare/CompareDialog.h"
#include "ui/compare/CompareView.h"
#include "ui/document/MaterialDocument.h"
#include "ui/panels/CompressPanel.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/window/MainWindow.h"

#include <QApplication>
#include <QChartView>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QScatterSeries>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTableWidget>
#include <QTest>
#include <QTimer>

#include <gtest/gtest.h>

namespace relief::test {
namespace {

using core::MapSlot;
using core::TextureFormat;

double meanDifference(const QImage& a, const QImage& b) {
  const QImage x = a.convertToFormat(QImage::Format_RGBA8888);
  const QImage y = b.convertToFormat(QImage::Format_RGBA8888);
  double sum = 0.0;
  for (int row = 0; row < x.height(); ++row) {
    const uchar* p = x.constScanLine(row);
    const uchar* q = y.constScanLine(row);
    for (int i = 0; i < x.width() * 4; ++i)
      sum += std::abs(int(p[i]) - int(q[i]));
  }
  return sum / (double(x.width()) * x.height() * 4.0 * 255.0);
}

// The top-left size x size texels of `map`, with its colour space and source bit depth.
core::Image corner(const core::Image& map, int size) {
  core::Image cut(size, size, map.channels(), map.colorSpace());
  cut.setSourceBitsPerChannel(map.sourceBitsPerChannel());
  for (int y = 0; y < size; ++y)
    std::copy_n(map.pixel(0, y), std::size_t(size) * std::size_t(map.channels()), cut.pixel(0, y));
  return cut;
}

class CompressPanelTest : public MainWindowFixture {
 protected:
  void SetUp() override { openWindow(1200, 760, samplePreset("bricks")); }
  ui::CompressPanel* panel() { return m_window->compressPanel(); }

  void choose(MapSlot slot, std::optional<TextureFormat> format,
              core::CompressionQuality quality = core::CompressionQuality::Fast) {
    QComboBox* box = panel()->formatBox(slot);
    box->setCurrentIndex(box->findData(format ? int(*format) : -1));
    ASSERT_GE(box->currentIndex(), 0);
    panel()->qualityBox(slot)->setCurrentIndex(panel()->qualityBox(slot)->findData(int(quality)));
  }
};

TEST_F(CompressPanelTest, CompressesInTheBackgroundAndTheViewportShowsTheBlocks) {
  const auto colour = document()->material().map(MapSlot::Color).image;
  const auto normal = document()->material().map(MapSlot::Normal).image;
  // BC6H is offered for the bricks' 16-bit height (enabled) and never for the sRGB colour map.
  {
    QComboBox* height = panel()->formatBox(MapSlot::Height);
    const int bc6h = height->findData(int(TextureFormat::Bc6h));
    ASSERT_GE(bc6h, 0);
    auto* items = qobject_cast<QStandardItemModel*>(height->model());
    ASSERT_NE(items, nullptr);
    EXPECT_TRUE(items->item(bc6h)->isEnabled());
    EXPECT_LT(panel()->formatBox(MapSlot::Color)->findData(int(TextureFormat::Bc6h)), 0);
  }
  choose(MapSlot::Color, TextureFormat::Bc1);
  choose(MapSlot::Normal, TextureFormat::Bc5);
  choose(MapSlot::Height, TextureFormat::Bc4);
  // The choices are document state: saved with the preset, undoable.
  ASSERT_TRUE(document()->compression(MapSlot::Normal).has_value());
  EXPECT_EQ(document()->compression(MapSlot::Normal)->format, TextureFormat::Bc5);
  ASSERT_TRUE(document()->compression(MapSlot::Color).has_value());
  EXPECT_EQ(document()->compression(MapSlot::Color)->quality, core::CompressionQuality::Fast);

  // The GUI keeps turning while the maps compress: a 10 ms timer ticks during the run.
  int ticks = 0;
  QTimer heartbeat;
  QObject::connect(&heartbeat, &QTimer::timeout, [&ticks] { ++ticks; });
  heartbeat.start(10);
  QSignalSpy finished(panel()->runner(), &ui::CompressionRunner::finished);
  QTest::mouseClick(panel()->compressButton(), Qt::LeftButton);
  EXPECT_TRUE(panel()->runner()->isRunning());
  EXPECT_FALSE(panel()->compressButton()->isEnabled());
  ASSERT_TRUE(finished.wait(120000));
  heartbeat.stop();
  EXPECT_GT(ticks, 3) << "the event loop stalled while compressing";

  ASSERT_EQ(panel()->outcomes().size(), 3u);
  EXPECT_EQ(panel()->resultsTable()->rowCount(), 3);
  const core::CompressionOutcome& bc5 = panel()->outcomes().at(MapSlot::Normal);
  ASSERT_TRUE(bc5.report.normal.has_value());
  EXPECT_LT(bc5.report.normal->meanDegrees, 1.0);
  EXPECT_EQ(bc5.texture->levels.size(), 11u);  // mipmaps on by default: 1024 .. 1
  // The document's maps are untouched: compression is a preview.
  EXPECT_EQ(document()->material().map(MapSlot::Color).image, colour);
  EXPECT_EQ(document()->material().map(MapSlot::Normal).image, normal);

  // The panel switched the viewport to the wipe; llvmpipe has every BC format, so the status
  // bar says the blocks went to the GPU as they are.
  ui::ViewportWidget* viewport = m_window->viewport();
  EXPECT_EQ(viewDocument()->compressedView(), ui::ViewDocument::CompressedView::Wipe);
  const QImage wipe = viewport->grabFramebuffer();
  QTest::qWait(50);
  QLabel* upload = m_window->compressedUploadLabel();
  EXPECT_TRUE(upload->isVisible());
  EXPECT_NE(upload->text().indexOf(QStringLiteral("Normal BC5 (ATI2, 3Dc) uploaded natively")), -1)
      << upload->text().toStdString();

  // Compressed maps change the picture a little; the original is the original again.
  panel()->viewBox()->setCurrentIndex(0);
  const QImage original = viewport->grabFramebuffer();
  panel()->viewBox()->setCurrentIndex(1);
  const QImage compressed = viewport->grabFramebuffer();
  const double change = meanDifference(original, compressed);
  EXPECT_GT(change, 0.0);
  EXPECT_LT(change, 3.0 / 255.0);
  EXPECT_GT(meanDifference(original, wipe), 0.0);
  // Save Viewport Image renders what the viewport shows, compressed maps included.
  const std::string folder = scratchFolder();
  ASSERT_TRUE(m_window->saveViewportImage(QString::fromStdString(folder + "/c.png"), 320, 200));
  panel()->viewBox()->setCurrentIndex(0);
  ASSERT_TRUE(m_window->saveViewportImage(QString::fromStdString(folder + "/o.png"), 320, 200));
  EXPECT_GT(meanDifference(QImage(QString::fromStdString(folder + "/c.png")),
                           QImage(QString::fromStdString(folder + "/o.png"))),
            0.0);

  // With native uploads off (Preferences) the same blocks are decoded by Relief: the status bar
  // says so and the picture stays the same to within filtering differences.
  panel()->viewBox()->setCurrentIndex(1);
  viewport->setNativeCompressedUploads(false);
  const QImage decoded = viewport->grabFramebuffer();
  EXPECT_NE(upload->text().indexOf(QStringLiteral("decoded by Relief (Preferences)")), -1)
      << upload->text().toStdString();
  EXPECT_LT(meanDifference(compressed, decoded), 1.0 / 255.0);
  viewport->setNativeCompressedUploads(true);

  // A new map in a slot drops that slot's stale preview.
  document()->setMap(MapSlot::Height, std::make_shared<core::Image>(64, 64, 1), QString());
  EXPECT_EQ(panel()->outcomes().count(MapSlot::Height), 0u);
  EXPECT_EQ(panel()->resultsTable()->rowCount(), 2);
}

TEST_F(CompressPanelTest, CancelLeavesTheMaterialAndTheEarlierResults) {
  choose(MapSlot::Color, std::nullopt);
  choose(MapSlot::Normal, std::nullopt);
  choose(MapSlot::Height, TextureFormat::Bc4);
  QSignalSpy finished(panel()->runner(), &ui::CompressionRunner::finished);
  panel()->compress();
  ASSERT_TRUE(finished.wait(120000));
  ASSERT_EQ(panel()->outcomes().size(), 1u);
  const auto earlier = panel()->outcomes().at(MapSlot::Height).texture;

  // A slow job (ASTC 4x4 at best), cancelled as soon as it reports progress.
  choose(MapSlot::Color, TextureFormat::Astc4x4, core::CompressionQuality::Best);
  const core::Material before = document()->material();
  QSignalSpy cancelled(panel()->runner(), &ui::CompressionRunner::cancelled);
  QSignalSpy progress(panel()->runner(), &ui::CompressionRunner::progress);
  panel()->compress();
  ASSERT_TRUE(progress.wait(60000));
  QTest::mouseClick(panel()->cancelButton(), Qt::LeftButton);
  ASSERT_TRUE(cancelled.wait(60000));
  EXPECT_TRUE(panel()->compressButton()->isEnabled());
  // Nothing from the cancelled run: the earlier BC4 result is still the only one.
  ASSERT_EQ(panel()->outcomes().size(), 1u);
  EXPECT_EQ(panel()->outcomes().at(MapSlot::Height).texture, earlier);
  for (MapSlot slot : core::kAllMapSlots)
    EXPECT_EQ(document()->material().map(slot).image, before.map(slot).image);
}

TEST_F(CompressPanelTest, TheCompareViewIsTexelExactAndShowsDifferences) {
  choose(MapSlot::Color, TextureFormat::Bc1);
  choose(MapSlot::Normal, std::nullopt);
  choose(MapSlot::Height, std::nullopt);
  QSignalSpy finished(panel()->runner(), &ui::CompressionRunner::finished);
  panel()->compress();
  ASSERT_TRUE(finished.wait(120000));
  panel()->openCompare();
  ui::CompareDialog* dialog = panel()->compareDialog();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
  ui::CompareView* view = dialog->view();
  const core::CompressionOutcome& outcome = panel()->outcomes().at(MapSlot::Color);

  // Zoomed to 8:1 about texel (20, 30) (fitted, the whole map is on screen, so it stays there),
  // with the wipe at the far right (all original), then the far left (all compressed): the
  // centre of the texel shows exactly that texel of each image, unsmoothed.
  view->setZoom(8.0, view->toWidget(QPointF(20.5, 30.5)));
  const auto texelColour = [&](double wipe) {
    view->setWipeFraction(wipe);
    const QImage picture = view->picture();
    const QPointF centre = view->toWidget(QPointF(20.5, 30.5));
    return picture.pixelColor(int(centre.x()), int(centre.y()));
  };
  const auto expected = [](const core::Image& image) {
    return QColor(int(std::lround(image.at(20, 30, 0) * 255.0f)),
                  int(std::lround(image.at(20, 30, 1) * 255.0f)),
                  int(std::lround(image.at(20, 30, 2) * 255.0f)));
  };
  EXPECT_EQ(texelColour(1.0), expected(*outcome.job.map));
  EXPECT_EQ(texelColour(0.0), expected(*outcome.decoded));

  // The read-out names the texel under the pointer and follows it when the picture moves under
  // a still pointer (a zoom), and is cleared when the pointer leaves.
  QSignalSpy hover(view, &ui::CompareView::hoverText);
  const QPointF pointer = view->toWidget(QPointF(20.5, 30.5));
  QTest::mouseMove(view, pointer.toPoint());
  ASSERT_FALSE(hover.isEmpty());
  EXPECT_TRUE(hover.last().front().toString().startsWith(QStringLiteral("texel 20, 30:")))
      << hover.last().front().toString().toStdString();
  view->setZoom(16.0, view->toWidget(QPointF(10.5, 10.5)));  // texel 10, 10 stays in place
  const QPointF texel = view->toTexel(pointer);
  EXPECT_TRUE(hover.last().front().toString().startsWith(
      QStringLiteral("texel %1, %2:").arg(int(texel.x())).arg(int(texel.y()))))
      << hover.last().front().toString().toStdString();
  QEvent leave(QEvent::Leave);
  QApplication::sendEvent(view, &leave);
  EXPECT_TRUE(hover.last().front().toString().isEmpty());
  view->setZoom(8.0, view->toWidget(QPointF(20.5, 30.5)));

  // Difference x100 and the thresholded view are different pictures from the wipe; the gain
  // slider is only enabled for the difference.
  dialog->modeBox()->setCurrentIndex(2);
  EXPECT_EQ(view->mode(), ui::CompareView::Mode::Difference);
  EXPECT_TRUE(dialog->gainSlider()->isEnabled());
  EXPECT_FALSE(dialog->thresholdBox()->isEnabled());
  dialog->gainSlider()->setValue(100);
  EXPECT_DOUBLE_EQ(view->gain(), 100.0);
  view->fitToView();
  const QImage difference = view->picture();
  dialog->modeBox()->setCurrentIndex(3);
  EXPECT_TRUE(dialog->thresholdBox()->isEnabled());
  const QImage thresholded = view->picture();
  EXPECT_GT(meanDifference(difference, thresholded), 0.0);
  // The FLIP error, measured off the GUI thread, then a heat map unlike either difference
  // picture; the gain applies to it (x100 saturates BC1's small error to red, x1 leaves it in
  // the ramp's blue end).
  dialog->modeBox()->setCurrentIndex(4);
  EXPECT_EQ(view->mode(), ui::CompareView::Mode::Flip);
  EXPECT_TRUE(dialog->gainSlider()->isEnabled());
  view->waitForFlip();
  const QImage flip = view->picture();
  EXPECT_GT(meanDifference(flip, difference), 0.0);
  EXPECT_GT(meanDifference(flip, thresholded), 0.0);
  const QPoint middle = view->toWidget(QPointF(20.5, 30.5)).toPoint();
  EXPECT_GT(flip.pixelColor(middle).red(), flip.pixelColor(middle).blue()) << "x100: saturated";
  dialog->gainSlider()->setValue(1);
  const QImage unamplified = view->picture();
  EXPECT_GT(unamplified.pixelColor(middle).blue(), unamplified.pixelColor(middle).red());
  // Block error: one colour a block of the format (BC1: 4x4), so the picture is constant inside
  // every block and differs from the FLIP map.
  dialog->modeBox()->setCurrentIndex(5);
  EXPECT_EQ(view->mode(), ui::CompareView::Mode::Blocks);
  EXPECT_TRUE(dialog->gainSlider()->isEnabled());
  dialog->gainSlider()->setValue(50);
  view->setZoom(8.0, view->toWidget(QPointF(20.5, 30.5)));
  const QImage blocks = view->picture();
  EXPECT_GT(meanDifference(blocks, flip), 0.0);
  const QPoint corner = view->toWidget(QPointF(20.1, 36.1)).toPoint();  // both in block (5, 9)
  const QPoint opposite = view->toWidget(QPointF(23.9, 39.9)).toPoint();
  ASSERT_TRUE(blocks.rect().contains(corner) && blocks.rect().contains(opposite));
  EXPECT_EQ(blocks.pixelColor(corner), blocks.pixelColor(opposite));
  dialog->channelBox()->setCurrentIndex(2);  // green alone
  EXPECT_EQ(view->channel(), std::optional<int>(1));
  dialog->close();
}

// The compare view's labels sit on a dark chip: over a white map (where white text alone would
// vanish) a good part of the label's pixels are dark.
TEST_F(CompressPanelTest, CompareViewLabelsAreReadableOverWhite) {
  auto white = std::make_shared<core::Image>(64, 64, 3, core::ColorSpace::Srgb);
  std::fill(white->data(), white->data() + white->valueCount(), 1.0f);
  ui::CompareView view;
  view.resize(400, 300);
  view.setImages(white, white);
  view.setZoom(40.0, QPointF(200, 150));  // the white map covers the whole view
  for (const auto mode : {ui::CompareView::Mode::Wipe, ui::CompareView::Mode::Difference}) {
    view.setMode(mode);
    const QImage picture = view.picture();
    int dark = 0, all = 0;
    for (int y = 8; y < 26; ++y) {
      for (int x = 8; x < 56; ++x, ++all)
        dark += qGray(picture.pixel(x, y)) < 100 ? 1 : 0;
    }
    EXPECT_GT(dark, all / 3) << dark << " of " << all;
  }
}

TEST_F(CompressPanelTest, CompareAllFormatsFillsTheTableAndChartAndHandsAFormatBack) {
  ui::CompareAllDialog* dialog = panel()->compareAllDialog();
  QSignalSpy finished(dialog->runner(), &ui::CompressionRunner::finished);
  // A 256x256 corner of the bricks' 16-bit height: the dialog's rows and chart do not depend on
  // the map's size, and every format on the whole 1024x1024 map took 50 s of the suite.
  const auto height = std::make_shared<const core::Image>(
      corner(*document()->material().map(MapSlot::Height).image, 256));
  dialog->start(MapSlot::Height, height, core::CompressionQuality::Fast, true, 3, 0.03);
  dialog->show();
  ASSERT_TRUE(finished.wait(240000));
  // Every format (BC6H too: the bricks' height is a 16-bit map), and under Zstandard each
  // format with RDO at two trades (lambda 8 and 32).
  std::size_t formats = 0;
  for (core::TextureFormat format : core::formatsForMap(*height, MapSlot::Height))
    formats += core::formatHasRdo(format) ? 3 : 1;
  EXPECT_EQ(dialog->table()->rowCount(), int(formats));
  EXPECT_EQ(dialog->chartView()->chart()->series().size(), qsizetype(formats));
  // A trade makes the file on disk smaller than its format's plain row, never larger.
  for (const core::CompressionOutcome& traded : dialog->outcomes()) {
    if (traded.job.settings.rdoLambda == 0.0f)
      continue;
    for (const core::CompressionOutcome& plain : dialog->outcomes()) {
      if (plain.job.settings.format == traded.job.settings.format &&
          plain.job.settings.rdoLambda == 0.0f) {
        EXPECT_LT(traded.report.size->ktx2Bytes, plain.report.size->ktx2Bytes)
            << core::textureFormatInfo(plain.job.settings.format).name << " RDO "
            << traded.job.settings.rdoLambda;
      }
    }
  }
  // Every row carries a finite quality and a rate matching the format's.
  for (const core::CompressionOutcome& outcome : dialog->outcomes()) {
    EXPECT_DOUBLE_EQ(outcome.report.size->bitsPerPixel,
                     core::bitsPerPixel(outcome.job.settings.format));
    EXPECT_GT(outcome.report.image.psnr, 30.0)
        << core::textureFormatInfo(outcome.job.settings.format).name;
    EXPECT_TRUE(outcome.report.height.has_value());
    // The size on disk is the KTX2 file at Zstandard level 3: the blocks (lossless, so never
    // much more than them) plus a header of under 1 KiB.
    EXPECT_EQ(outcome.report.size->zstdLevel, 3);
    EXPECT_GT(outcome.report.size->ktx2Bytes, 0u);
    EXPECT_LT(outcome.report.size->ktx2Bytes, outcome.report.size->bytes + 1024u);
    // With mipmaps, as the panel counts them: the chain adds a third to level 0's blocks.
    const double levelZero =
        core::bitsPerPixel(outcome.job.settings.format) * height->width() * height->height() / 8.0;
    EXPECT_GT(double(outcome.report.size->bytes), 1.3 * levelZero);
  }
  const QString diskHeader = dialog->table()->horizontalHeaderItem(2)->text();
  EXPECT_TRUE(diskHeader.contains(QStringLiteral("Zstd 3"))) << diskHeader.toStdString();
  EXPECT_TRUE(diskHeader.contains(QStringLiteral("with mipmaps"))) << diskHeader.toStdString();
  // A FLIP column (core/compression/Flip.h) beside SSIM, a value in (0, 1) for every lossy row.
  int flipColumn = -1;
  for (int c = 0; c < dialog->table()->columnCount(); ++c)
    if (dialog->table()->horizontalHeaderItem(c)->text() == QStringLiteral("FLIP"))
      flipColumn = c;
  ASSERT_GE(flipColumn, 0);
  for (int row = 0; row < dialog->table()->rowCount(); ++row) {
    const double flip = dialog->table()->item(row, flipColumn)->data(Qt::UserRole).toDouble();
    EXPECT_GT(flip, 0.0) << row;
    EXPECT_LT(flip, 1.0) << row;
  }
  // No two shown point labels sit closer than a label's size (they printed over each other), and
  // at least one is shown.
  std::vector<QPointF> shown;
  for (QAbstractSeries* series : dialog->chartView()->chart()->series()) {
    auto* scatter = qobject_cast<QScatterSeries*>(series);
    ASSERT_NE(scatter, nullptr);
    if (scatter->pointLabelsVisible())
      shown.push_back(dialog->chartView()->chart()->mapToPosition(scatter->at(0), scatter));
  }
  ASSERT_FALSE(shown.empty());
  const QRectF plot = dialog->chartView()->chart()->plotArea();
  for (std::size_t i = 0; i < shown.size(); ++i) {
    for (std::size_t j = i + 1; j < shown.size(); ++j) {
      EXPECT_TRUE(std::abs(shown[i].x() - shown[j].x()) >= 0.2 * plot.width() ||
                  std::abs(shown[i].y() - shown[j].y()) >= 0.06 * plot.height())
          << "labels " << i << " and " << j << " overlap";
    }
  }
  // Pick EAC R11 and use it.
  for (int row = 0; row < dialog->table()->rowCount(); ++row) {
    if (dialog->table()->item(row, 0)->data(Qt::UserRole).toInt() == int(TextureFormat::EacR11))
      dialog->table()->selectRow(row);
  }
  ASSERT_EQ(dialog->selectedFormat(), TextureFormat::EacR11);
  QPushButton* use = nullptr;
  for (QPushButton* button : dialog->findChildren<QPushButton*>()) {
    if (button->text() == QStringLiteral("Use Format"))
      use = button;
  }
  ASSERT_NE(use, nullptr);
  QTest::mouseClick(use, Qt::LeftButton);
  EXPECT_EQ(panel()->formatBox(MapSlot::Height)->currentData().toInt(), int(TextureFormat::EacR11));
  ASSERT_TRUE(document()->compression(MapSlot::Height).has_value());
  EXPECT_EQ(document()->compression(MapSlot::Height)->format, TextureFormat::EacR11);
  dialog->close();
}

}  // namespace
}  // namespace relief::test
