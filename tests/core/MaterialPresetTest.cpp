// Presets: the bundled samples load whole; a save-and-load round trip keeps everything; bad
// files are refused or reported with the file's name.
#include "core/ImageIO.h"
#include "core/MaterialPreset.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace relief::core {
namespace {

using test::samplePreset;
using test::scratchFolder;

void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(MaterialPreset, EverySampleLoadsWithAllItsMaps) {
  for (const char* name : {"bricks", "cobblestones", "tiles"}) {
    Result<LoadedPreset> loaded = loadPreset(samplePreset(name));
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_TRUE(loaded->warnings.empty()) << loaded->warnings.front();
    const Material& material = loaded->material;
    EXPECT_EQ(material.name(), name);
    for (MapSlot slot : {MapSlot::Color, MapSlot::Normal, MapSlot::Height}) {
      ASSERT_TRUE(material.hasMap(slot)) << name << " " << mapSlotName(slot);
      EXPECT_EQ(material.image(slot)->width(), 1024);
      EXPECT_EQ(material.image(slot)->height(), 1024);
      EXPECT_EQ(material.image(slot)->colorSpace(), mapSlotColorSpace(slot));
    }
    EXPECT_EQ(material.image(MapSlot::Height)->sourceBitsPerChannel(), 16) << name;
  }
}

TEST(MaterialPreset, SaveThenLoadKeepsParametersAndMaps) {
  Result<LoadedPreset> original = loadPreset(samplePreset("tiles"));
  ASSERT_TRUE(original.ok()) << original.error();
  Material material = original->material;
  material.setParameter(ParamId::Tiling, 3.25);
  material.setParameter(ParamId::NormalYDown, 1.0);
  const std::string folder = scratchFolder() + "/saved";
  std::filesystem::create_directories(folder);
  const std::string path = folder + "/copy.relief";
  ASSERT_TRUE(savePreset(material, path).ok());

  Result<LoadedPreset> reloaded = loadPreset(path);
  ASSERT_TRUE(reloaded.ok()) << reloaded.error();
  EXPECT_TRUE(reloaded->warnings.empty());
  EXPECT_EQ(reloaded->material.parameters(), material.parameters());
  EXPECT_EQ(reloaded->material.technique(), material.technique());
  for (MapSlot slot : kAllMapSlots) {
    ASSERT_EQ(reloaded->material.hasMap(slot), material.hasMap(slot));
    if (!material.hasMap(slot))
      continue;
    EXPECT_EQ(std::filesystem::canonical(reloaded->material.map(slot).sourcePath),
              std::filesystem::canonical(material.map(slot).sourcePath));
    EXPECT_EQ(*reloaded->material.image(slot), *material.image(slot));
  }
}

TEST(MaterialPreset, RefusesWhatItCannotRead) {
  const std::string folder = scratchFolder();
  const struct {
    const char* file;
    const char* text;
    const char* expected;
  } cases[] = {
      {"notjson.relief", "this is not json", "not a valid preset"},
      {"truncated.relief", "{\"format\": \"relief-material\", \"version\": 1, \"maps\": {",
       "not a valid preset"},
      {"array.relief", "[1, 2, 3]", "not a JSON object"},
      {"otherformat.relief", "{\"format\": \"something\", \"version\": 1}", "not a Relief preset"},
      {"future.relief", "{\"format\": \"relief-material\", \"version\": 99}", "newer Relief"},
      {"badversion.relief", "{\"format\": \"relief-material\", \"version\": \"one\"}",
       "positive integer"},
  };
  for (const auto& c : cases) {
    const std::string path = folder + "/" + c.file;
    writeText(path, c.text);
    Result<LoadedPreset> loaded = loadPreset(path);
    ASSERT_FALSE(loaded.ok()) << c.file;
    EXPECT_NE(loaded.error().find(c.file), std::string::npos) << loaded.error();
    EXPECT_NE(loaded.error().find(c.expected), std::string::npos) << loaded.error();
  }
  EXPECT_FALSE(loadPreset(folder + "/absent.relief").ok());
}

TEST(MaterialPreset, LoadsTheRestAndReportsWhatIsWrong) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/partial.relief";
  const std::string colorPath = test::sourcePath("samples/tiles/tiles_color.png");
  writeText(path,
            "{\"format\": \"relief-material\", \"version\": 1,"
            " \"maps\": {\"color\": {\"path\": \"" +
                colorPath +
                "\"},"
                "            \"normal\": {\"path\": \"missing_normal.png\"}},"
                " \"technique\": \"warp-drive\","
                " \"parameters\": {\"tiling\": 500, \"specular\": \"shiny\", \"bogus\": 1}}");
  Result<LoadedPreset> loaded = loadPreset(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_TRUE(loaded->material.hasMap(MapSlot::Color));
  EXPECT_FALSE(loaded->material.hasMap(MapSlot::Normal));
  EXPECT_EQ(loaded->material.parameter(ParamId::Tiling), parameterSpec(ParamId::Tiling).maximum);
  std::string all;
  for (const std::string& warning : loaded->warnings) {
    EXPECT_NE(warning.find("partial.relief"), std::string::npos) << warning;
    all += warning + "\n";
  }
  EXPECT_NE(all.find("missing_normal.png"), std::string::npos) << all;
  EXPECT_NE(all.find("warp-drive"), std::string::npos) << all;
  EXPECT_NE(all.find("tiling"), std::string::npos) << all;
  EXPECT_NE(all.find("specular"), std::string::npos) << all;
  EXPECT_NE(all.find("bogus"), std::string::npos) << all;
}

}  // namespace
}  // namespace relief::core
