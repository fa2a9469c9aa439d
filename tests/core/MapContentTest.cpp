// Telling a normal map by its texels (core/material/MapContent.h): normal maps made from a
// height field in either Y convention read as normal maps; colour maps, photographs, grey height
// maps and a flat blue colour that is not unit vectors do not.
#include "core/generators/NormalFromHeight.h"
#include "core/image/ImageIO.h"
#include "core/material/MapContent.h"
#include "support/TestPaths.h"
#include "support/TestPhotos.h"

#include <gtest/gtest.h>

#include <cmath>

namespace relief::core {
namespace {

Image loaded(const std::string& relative) {
  Result<Image> image = loadImage(test::sourcePath(relative));
  EXPECT_TRUE(image.ok()) << image.error();
  return image.ok() ? std::move(image).value() : Image();
}

TEST(MapContent, NormalMapsReadAsNormalMaps) {
  EXPECT_TRUE(looksLikeNormalMap(loaded("samples/bricks/bricks_normal.png")));
  EXPECT_TRUE(looksLikeNormalMap(loaded("samples/cobblestones/cobblestones_normal.png")));
  // A bumpy field's normals, with green up and down.
  Image height(96, 96, 1);
  for (int y = 0; y < 96; ++y) {
    for (int x = 0; x < 96; ++x)
      height.at(x, y, 0) = float(0.5 + 0.5 * std::sin(x * 0.3) * std::cos(y * 0.2));
  }
  NormalFromHeightOptions options;
  options.strength = 4.0f;
  EXPECT_TRUE(looksLikeNormalMap(normalMapFromHeight(height, options)));
  options.convention = NormalConvention::DirectX;
  EXPECT_TRUE(looksLikeNormalMap(normalMapFromHeight(height, options)));
}

TEST(MapContent, ColourGreyAndFlatBlueDoNot) {
  EXPECT_FALSE(looksLikeNormalMap(loaded("samples/bricks/bricks_color.png")));
  EXPECT_FALSE(looksLikeNormalMap(loaded("samples/tiles/tiles_color.png")));
  EXPECT_FALSE(looksLikeNormalMap(loaded("samples/bricks/bricks_height.png")));  // one channel
  for (const Image& photo : test::photographCrops())
    EXPECT_FALSE(looksLikeNormalMap(photo));
  Image grey(8, 8, 3);
  for (std::size_t i = 0; i < grey.valueCount(); ++i)
    grey.data()[i] = 0.5f;  // a zero vector, not a unit one
  EXPECT_FALSE(looksLikeNormalMap(grey));
  Image sky(8, 8, 3);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      sky.at(x, y, 0) = 0.5f;
      sky.at(x, y, 1) = 0.5f;
      sky.at(x, y, 2) = 0.8f;  // bluish, but (0, 0, 0.6) is no unit vector
    }
  }
  EXPECT_FALSE(looksLikeNormalMap(sky));
}

}  // namespace
}  // namespace relief::core
