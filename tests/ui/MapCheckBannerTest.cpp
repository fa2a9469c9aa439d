// The Maps dock's map check (ui/panels/MapCheckBanner): the bundled bricks raise no warning; a
// DirectX normal map (the sample's with green inverted, as Unreal's exports store it) does, with
// the fix as one undoable click that makes the warning go; a height map of another surface is
// named without a fix.
#include "core/image/ImageIO.h"
#include "support/TestPaths.h"
#include "ui/document/MaterialDocument.h"
#include "ui/panels/MapCheckBanner.h"

#include <QLabel>
#include <QPushButton>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <memory>

namespace relief::test {
namespace {

std::shared_ptr<const core::Image> sampleMap(const std::string& material, const char* slot) {
  core::Result<core::Image> image =
      core::loadImage(sourcePath("samples/") + material + "/" + material + "_" + slot + ".png");
  EXPECT_TRUE(image.ok()) << image.error();
  return std::make_shared<core::Image>(std::move(image).value());
}

TEST(MapCheckBanner, WarnsOfADirectXNormalMapAndFixesItInOneUndoableClick) {
  ui::MaterialDocument document;
  ui::MapCheckBanner banner(&document);
  document.setMap(core::MapSlot::Normal, sampleMap("bricks", "normal"), QStringLiteral("n.png"));
  document.setMap(core::MapSlot::Height, sampleMap("bricks", "height"), QStringLiteral("h.png"));
  banner.waitForCheck();
  EXPECT_TRUE(banner.isHidden()) << "the bundled pair agrees";

  core::Image flipped = *sampleMap("bricks", "normal");
  for (int y = 0; y < flipped.height(); ++y) {
    for (int x = 0; x < flipped.width(); ++x)
      flipped.at(x, y, 1) = 1.0f - flipped.at(x, y, 1);
  }
  document.setMap(core::MapSlot::Normal, std::make_shared<core::Image>(std::move(flipped)),
                  QStringLiteral("wall_dx.png"));
  banner.waitForCheck();
  ASSERT_FALSE(banner.isHidden());
  const QString text = banner.findChild<QLabel*>()->text();
  EXPECT_TRUE(text.contains(QStringLiteral("wall_dx.png is a DirectX"))) << text.toStdString();
  auto* flipY = banner.findChild<QPushButton*>(QStringLiteral("mapCheckFlipY"));
  auto* invert = banner.findChild<QPushButton*>(QStringLiteral("mapCheckInvertHeight"));
  ASSERT_TRUE(flipY && invert);
  EXPECT_FALSE(flipY->isHidden());
  EXPECT_TRUE(invert->isHidden()) << "the height map is the right way up";

  const int steps = document.undoStack()->count();
  flipY->click();
  banner.waitForCheck();
  EXPECT_TRUE(document.material().parameterFlag(core::ParamId::NormalYDown));
  EXPECT_EQ(document.undoStack()->count(), steps + 1) << "the fix is one undo step";
  EXPECT_TRUE(banner.isHidden()) << "read as DirectX, the maps agree";
  document.undoStack()->undo();
  banner.waitForCheck();
  EXPECT_FALSE(banner.isHidden()) << "undone, the warning is back";
}

TEST(MapCheckBanner, NamesAHeightMapOfAnotherSurface) {
  ui::MaterialDocument document;
  ui::MapCheckBanner banner(&document);
  document.setMap(core::MapSlot::Normal, sampleMap("bricks", "normal"),
                  QStringLiteral("bricks_normal.png"));
  document.setMap(core::MapSlot::Height, sampleMap("cobblestones", "height"),
                  QStringLiteral("cobblestones_height.png"));
  banner.waitForCheck();
  ASSERT_FALSE(banner.isHidden());
  EXPECT_TRUE(banner.findChild<QLabel*>()->text().contains(
      QStringLiteral("do not describe the same surface")));
  EXPECT_TRUE(banner.findChild<QPushButton*>(QStringLiteral("mapCheckFlipY"))->isHidden());
  EXPECT_TRUE(banner.findChild<QPushButton*>(QStringLiteral("mapCheckInvertHeight"))->isHidden());
}

}  // namespace
}  // namespace relief::test
