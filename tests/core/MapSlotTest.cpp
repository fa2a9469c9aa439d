// Assigning dropped files to map slots by the hints in their names.
#include "core/material/MapSlot.h"

#include <gtest/gtest.h>

namespace relief::core {
namespace {

TEST(MapSlot, GuessesFromCommonNamingSchemes) {
  EXPECT_EQ(guessMapSlotFromFileName("bricks_height.png"), MapSlot::Height);
  EXPECT_EQ(guessMapSlotFromFileName("/some/dir/bricks_normal.png"), MapSlot::Normal);
  EXPECT_EQ(guessMapSlotFromFileName("Bricks_Color.PNG"), MapSlot::Color);
  EXPECT_EQ(guessMapSlotFromFileName("rock_albedo.jpg"), MapSlot::Color);
  EXPECT_EQ(guessMapSlotFromFileName("wood-diffuse.tga"), MapSlot::Color);
  EXPECT_EQ(guessMapSlotFromFileName("T_Wall_BaseColor.tga"), MapSlot::Color);
  EXPECT_EQ(guessMapSlotFromFileName("rock_nor_gl_4k.exr"), MapSlot::Normal);
  EXPECT_EQ(guessMapSlotFromFileName("ground_disp.exr"), MapSlot::Height);
  EXPECT_EQ(guessMapSlotFromFileName("ground_AO.png"), MapSlot::AmbientOcclusion);
  EXPECT_EQ(guessMapSlotFromFileName("ground_roughness.png"), MapSlot::Roughness);
  EXPECT_EQ(guessMapSlotFromFileName("T_Hull_Metallic.tga"), MapSlot::Metallic);
  EXPECT_EQ(guessMapSlotFromFileName("hull-metalness.png"), MapSlot::Metallic);
  // The last hint wins: a height map made from a normal map.
  EXPECT_EQ(guessMapSlotFromFileName("wall_normal_height.png"), MapSlot::Height);
}

TEST(MapSlot, DoesNotGuessFromPartsOfWords) {
  EXPECT_EQ(guessMapSlotFromFileName("minor.png"), std::nullopt);  // contains "nor"
  EXPECT_EQ(guessMapSlotFromFileName("photo.png"), std::nullopt);
  EXPECT_EQ(guessMapSlotFromFileName("aorta.png"), std::nullopt);  // starts with "ao"
  EXPECT_EQ(guessMapSlotFromFileName("normalized.png"), std::nullopt);
}

// Packed occlusion/roughness/metallic files by their engines' names, and nothing else.
// Game data's short suffixes (Cube 2 and Red Eclipse name their texture slots d, n, z, s), as the
// name's last word only.
TEST(MapSlot, GuessesFromGameDataSuffixes) {
  EXPECT_EQ(guessMapSlotFromFileName("wall_n.png"), MapSlot::Normal);
  EXPECT_EQ(guessMapSlotFromFileName("stone_ground_tiles_gk_v01_nm.jpg"), MapSlot::Normal);
  EXPECT_EQ(guessMapSlotFromFileName("stone_ground_tiles_gk_v01_hm.jpg"), MapSlot::Height);
  EXPECT_EQ(guessMapSlotFromFileName("floor_z.png"), MapSlot::Height);
  EXPECT_EQ(guessMapSlotFromFileName("floor_H.tga"), MapSlot::Height);
  EXPECT_EQ(guessMapSlotFromFileName("floor_d.tga"), MapSlot::Color);
  EXPECT_EQ(guessMapSlotFromFileName("stone_ground_tiles_gk_v01_cc.jpg"), MapSlot::Color);
  EXPECT_EQ(guessMapSlotFromFileName("floor_diff.png"), MapSlot::Color);
  EXPECT_EQ(guessMapSlotFromFileName("floor_nrm.png"), MapSlot::Normal);
  EXPECT_EQ(guessMapSlotFromFileName("floor_rough.png"), MapSlot::Roughness);
  EXPECT_EQ(guessMapSlotFromFileName("floor_ao.png"), MapSlot::AmbientOcclusion);
  // Not as a first or middle word, nor alone.
  EXPECT_EQ(guessMapSlotFromFileName("n_wall.png"), std::nullopt);
  EXPECT_EQ(guessMapSlotFromFileName("wall_d_final.png"), std::nullopt);
  EXPECT_EQ(guessMapSlotFromFileName("z.png"), std::nullopt);
  // Specular and gloss maps have no slot: recognised, never guessed into another.
  for (const char* name :
       {"floor_s.png", "floor_spec.jpg", "tiles_gk_v01_sc.jpg", "stone_Gloss.png"}) {
    EXPECT_EQ(guessMapSlotFromFileName(name), std::nullopt) << name;
    EXPECT_TRUE(isSpecularFileName(name)) << name;
  }
  EXPECT_FALSE(isSpecularFileName("floor_n.png"));
  EXPECT_FALSE(isSpecularFileName("spec.png"));
}

TEST(MapSlot, RecognisesOrmTexturesByName) {
  EXPECT_TRUE(isOrmFileName("T_Rock_ORM.png"));
  EXPECT_TRUE(isOrmFileName("/textures/rocky_trail_arm_4k.exr"));  // Poly Haven
  EXPECT_FALSE(isOrmFileName("storm.png"));
  EXPECT_FALSE(isOrmFileName("farm_field_color.png"));
  EXPECT_FALSE(isOrmFileName("rock_roughness.png"));
}

TEST(MapSlot, ColourIsSrgbAndDataIsLinear) {
  EXPECT_EQ(mapSlotColorSpace(MapSlot::Color), ColorSpace::Srgb);
  for (MapSlot slot : {MapSlot::Normal, MapSlot::Height, MapSlot::AmbientOcclusion,
                       MapSlot::Roughness, MapSlot::Metallic}) {
    EXPECT_EQ(mapSlotColorSpace(slot), ColorSpace::Linear);
  }
}

// What an empty slot means to the shading: no occlusion (AO 1), the top surface (height 1), the
// roughness parameter alone (0 in the map), and a metallic texel of 1 that lets the metallic
// factor through (glTF 2.0's metallicRoughness convention).
TEST(MapSlot, TheTableSaysWhatEachSlotHoldsAndWhatEmptyMeans) {
  EXPECT_EQ(mapSlotTexels(MapSlot::Color), MapTexels::Colour);
  EXPECT_EQ(mapSlotTexels(MapSlot::Normal), MapTexels::Normal);
  for (MapSlot slot :
       {MapSlot::Height, MapSlot::AmbientOcclusion, MapSlot::Roughness, MapSlot::Metallic}) {
    EXPECT_EQ(mapSlotTexels(slot), MapTexels::Scalar) << mapSlotName(slot);
  }
  EXPECT_EQ(mapSlotNeutralValue(MapSlot::Height), 1.0f);
  EXPECT_EQ(mapSlotNeutralValue(MapSlot::AmbientOcclusion), 1.0f);
  EXPECT_EQ(mapSlotNeutralValue(MapSlot::Roughness), 0.0f);
  EXPECT_EQ(mapSlotNeutralValue(MapSlot::Metallic), 1.0f);
}

}  // namespace
}  // namespace relief::core
