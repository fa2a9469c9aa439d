// The Maps dock's Make Tileable (ui/panels/TileableBar): a crop of a sample set, which no longer
// tiles, comes out tiling in every map with one click as one undo step (undo gives back the very
// maps it replaced); the bundled samples, which tile already, are left alone with a message.
#include "core/generators/Tileable.h"
#include "core/image/ImageIO.h"
#include "support/TestPaths.h"
#include "ui/document/MaterialDocument.h"
#include "ui/panels/TileableBar.h"

#include <QLabel>
#include <QPushButton>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <memory>

namespace relief::test {
namespace {

std::shared_ptr<const core::Image> sampleMap(const char* slot, int crop) {
  core::Result<core::Image> image =
      core::loadImage(sourcePath("samples/cobblestones/cobblestones_") + slot + ".png");
  EXPECT_TRUE(image.ok()) << image.error();
  if (crop == 0)
    return std::make_shared<core::Image>(std::move(image).value());
  core::Image part(crop, crop, image->channels(), image->colorSpace());
  for (int y = 0; y < crop; ++y)
    for (int x = 0; x < crop; ++x)
      for (int c = 0; c < image->channels(); ++c)
        part.at(x, y, c) = image->at(x + 101, y + 257, c);
  return std::make_shared<core::Image>(std::move(part));
}

TEST(TileableBar, MakesEveryMapTileInOneUndoableClick) {
  ui::MaterialDocument document;
  ui::TileableBar bar(&document);
  auto* run = bar.findChild<QPushButton*>(QStringLiteral("makeTileable"));
  ASSERT_TRUE(run);
  EXPECT_FALSE(run->isEnabled()) << "no maps yet";
  const auto color = sampleMap("color", 256), normal = sampleMap("normal", 256),
             height = sampleMap("height", 256);
  document.setMap(core::MapSlot::Color, color, QStringLiteral("c.png"));
  document.setMap(core::MapSlot::Normal, normal, QStringLiteral("n.png"));
  document.setMap(core::MapSlot::Height, height, QStringLiteral("h.png"));
  ASSERT_TRUE(run->isEnabled());
  ASSERT_GT(core::wrapSeamRatio(*color, false), 1.5) << "the crop does not tile";

  const int steps = document.undoStack()->count();
  run->click();
  bar.waitForRun();
  EXPECT_EQ(document.undoStack()->count(), steps + 1) << "one undo step";
  for (core::MapSlot slot : {core::MapSlot::Color, core::MapSlot::Normal, core::MapSlot::Height}) {
    const core::MaterialMap& map = document.material().map(slot);
    ASSERT_TRUE(map.image);
    EXPECT_EQ(map.image->width(), 256);
    EXPECT_LE(core::wrapSeamRatio(*map.image, false), 1.2) << core::mapSlotName(slot);
    EXPECT_LE(core::wrapSeamRatio(*map.image, true), 1.2) << core::mapSlotName(slot);
  }
  const QString report = bar.findChild<QLabel*>(QStringLiteral("tileableReport"))->text();
  EXPECT_TRUE(report.contains(QStringLiteral("seam"))) << report.toStdString();

  document.undoStack()->undo();
  EXPECT_EQ(document.material().map(core::MapSlot::Color).image, color);
  EXPECT_EQ(document.material().map(core::MapSlot::Normal).image, normal);
  EXPECT_EQ(document.material().map(core::MapSlot::Height).image, height);
}

TEST(TileableBar, LeavesMapsThatTileAlone) {
  ui::MaterialDocument document;
  ui::TileableBar bar(&document);
  const auto color = sampleMap("color", 0);
  document.setMap(core::MapSlot::Color, color, QStringLiteral("c.png"));
  const int steps = document.undoStack()->count();
  bar.findChild<QPushButton*>(QStringLiteral("makeTileable"))->click();
  bar.waitForRun();
  EXPECT_EQ(document.undoStack()->count(), steps);
  EXPECT_EQ(document.material().map(core::MapSlot::Color).image, color);
  const QString report = bar.findChild<QLabel*>(QStringLiteral("tileableReport"))->text();
  EXPECT_TRUE(report.contains(QStringLiteral("already tile"))) << report.toStdString();
}

}  // namespace
}  // namespace relief::test
