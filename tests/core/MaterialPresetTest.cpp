// Presets: the bundled samples load whole; save -> load -> save is exact and keeps keys this
// program does not know; bad files are refused or reported with the file's name; versions 1
// and 2 migrate; a failed save leaves the old file byte for byte; maps made in the editor are
// written beside the preset.
#include "core/image/ImageIO.h"
#include "core/preset/MaterialPreset.h"
#include "core/preset/OrmTexture.h"
#include "support/TestPaths.h"

#include <QJsonDocument>
#include <QJsonObject>

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>

namespace relief::core {
namespace {

using test::samplePreset;
using test::scratchFolder;

void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string freshFolder(const std::string& name) {
  const std::string folder = scratchFolder() + "/" + name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

TEST(MaterialPreset, EverySampleLoadsWithAllItsMaps) {
  for (const char* name : {"bricks", "cobblestones", "tiles"}) {
    Result<LoadedPreset> loaded = loadPreset(samplePreset(name));
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_TRUE(loaded->warnings.empty()) << loaded->warnings.front();
    const Material& material = loaded->preset.material;
    EXPECT_EQ(material.name(), name);
    for (MapSlot slot : {MapSlot::Color, MapSlot::Normal, MapSlot::Height}) {
      ASSERT_TRUE(material.hasMap(slot)) << name << " " << mapSlotName(slot);
      EXPECT_EQ(material.image(slot)->width(), 1024);
      EXPECT_EQ(material.image(slot)->colorSpace(), mapSlotColorSpace(slot));
    }
    EXPECT_EQ(material.image(MapSlot::Height)->sourceBitsPerChannel(), 16) << name;
  }
}

TEST(MaterialPreset, SaveLoadSaveIsExactAndKeepsUnknownKeys) {
  Result<LoadedPreset> original = loadPreset(samplePreset("tiles"));
  ASSERT_TRUE(original.ok()) << original.error();
  Preset preset = original->preset;
  preset.material.setParameter(ParamId::Tiling, 3.25);
  preset.material.setParameter(ParamId::NormalYDown, 1.0);
  preset.material.setParameter(ParamId::ShadowMode, double(ShadowMode::Hard));
  preset.compression[std::size_t(MapSlot::Normal)] =
      CompressionSettings{TextureFormat::Bc5, CompressionQuality::Best, false, 12};
  preset.compression[std::size_t(MapSlot::Color)] = CompressionSettings{TextureFormat::Bc1,
                                                                        CompressionQuality::Fast,
                                                                        true,
                                                                        0,
                                                                        true,
                                                                        MipFilter::Kaiser,
                                                                        false,
                                                                        0.375f,
                                                                        6.5f};
  OrbitCamera camera;
  camera.yawDeg = -40.0f;
  camera.target = glm::vec3(0.1f, 0.2f, 0.3f);
  preset.view.camera = camera;
  DirectionalLight light;
  light.azimuthDeg = 210.0f;
  light.color = glm::vec3(1.0f, 0.5f, 0.25f);
  preset.view.light = light;
  preset.view.display = DisplayTransform{1.5f, ToneMapper::PbrNeutral};
  preset.view.mesh = "torus";
  Environment environment;
  environment.source = "sky";
  environment.intensity = 2.5f;
  environment.rotationDeg = -30.0f;
  environment.background = Background::Blurred;
  preset.view.environment = environment;
  // Keys from a future tool, at every level.
  preset.preserved.insert(QStringLiteral("pipelineTag"), QStringLiteral("hero-asset"));
  QJsonObject maps = preset.preserved.value(QStringLiteral("maps")).toObject();
  QJsonObject color = maps.value(QStringLiteral("color")).toObject();
  color.insert(QStringLiteral("sourceTool"), QStringLiteral("scanner-7"));
  maps.insert(QStringLiteral("color"), color);
  preset.preserved.insert(QStringLiteral("maps"), maps);

  const std::string folder = freshFolder("roundtrip");
  const std::string first = folder + "/first.relief";
  ASSERT_TRUE(savePreset(preset, first).ok());
  Result<LoadedPreset> reloaded = loadPreset(first);
  ASSERT_TRUE(reloaded.ok()) << reloaded.error();
  EXPECT_TRUE(reloaded->warnings.empty()) << reloaded->warnings.front();
  const Preset& again = reloaded->preset;
  EXPECT_EQ(again.material.parameters(), preset.material.parameters());
  EXPECT_EQ(again.material.technique(), preset.material.technique());
  EXPECT_EQ(again.compression, preset.compression);
  ASSERT_TRUE(again.view.camera && again.view.light);
  EXPECT_EQ(again.view.camera->yawDeg, -40.0f);
  EXPECT_EQ(again.view.camera->target, camera.target);
  EXPECT_EQ(again.view.light->color, light.color);
  EXPECT_EQ(again.view.display, preset.view.display);
  EXPECT_EQ(again.view.environment, preset.view.environment);
  EXPECT_EQ(again.view.mesh, "torus");
  for (MapSlot slot : kAllMapSlots) {
    ASSERT_EQ(again.material.hasMap(slot), preset.material.hasMap(slot));
    if (!preset.material.hasMap(slot))
      continue;
    EXPECT_EQ(*again.material.image(slot), *preset.material.image(slot));
  }
  EXPECT_EQ(again.preserved.value(QStringLiteral("pipelineTag")).toString(),
            QStringLiteral("hero-asset"));

  // Saved again without changes: the same bytes.
  const std::string second = folder + "/second.relief";
  ASSERT_TRUE(savePreset(again, second).ok());
  EXPECT_EQ(readText(first), readText(second));
  EXPECT_NE(readText(second).find("scanner-7"), std::string::npos);
}

TEST(MaterialPreset, RefusesWhatItCannotRead) {
  const std::string folder = freshFolder("refused");
  const struct {
    const char* file;
    const char* text;
    const char* expected;
  } cases[] = {
      {"notjson.relief", "this is not json", "not a valid preset"},
      {"truncated.relief", "{\"format\": \"relief-material\", \"version\": 2, \"maps\": {",
       "not a valid preset"},
      {"array.relief", "[1, 2, 3]", "not a JSON object"},
      {"otherformat.relief", "{\"format\": \"something\", \"version\": 1}", "not a Relief preset"},
      {"future.relief", "{\"format\": \"relief-material\", \"version\": 99}", "newer Relief"},
      {"badversion.relief", "{\"format\": \"relief-material\", \"version\": \"one\"}",
       "positive integer"},
      {"empty.relief", "", "the file is empty"},
      // Beyond double range: not a number JSON can hold (Qt's parser says so, with the byte).
      {"huge.relief",
       "{\"format\": \"relief-material\", \"version\": 2, \"parameters\": "
       "{\"tiling\": 1e400}}",
       "illegal number"},
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
  const std::string folder = freshFolder("partial");
  const std::string path = folder + "/partial.relief";
  const std::string colorPath = test::sourcePath("samples/tiles/tiles_color.png");
  writeText(path,
            "{\"format\": \"relief-material\", \"version\": 2,"
            " \"maps\": {\"color\": {\"path\": \"" +
                colorPath +
                "\", \"compression\": {\"format\": \"bc1\", \"mipFilter\": \"lanczos9\"}},"
                "            \"normal\": {\"path\": \"missing_normal.png\","
                "                         \"compression\": {\"format\": \"zip\"}}},"
                " \"technique\": \"warp-drive\","
                " \"parameters\": {\"tiling\": 500, \"specular\": \"shiny\", \"bogus\": 1,"
                "                  \"heightScale\": 1e300, \"normalYDown\": 3},"
                " \"view\": {\"camera\": {\"pitch\": \"high\", \"distance\": -4},"
                "            \"light\": {\"color\": [1, 2]},"
                "            \"display\": {\"exposure\": 40, \"toneMapping\": \"filmic\"},"
                "            \"environment\": {\"source\": \"sky\", \"intensity\": 99,"
                "                            \"background\": \"starfield\"}}}");
  Result<LoadedPreset> loaded = loadPreset(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  const Material& material = loaded->preset.material;
  EXPECT_TRUE(material.hasMap(MapSlot::Color));
  EXPECT_FALSE(material.hasMap(MapSlot::Normal));
  ASSERT_TRUE(loaded->preset.compression[std::size_t(MapSlot::Color)].has_value());
  EXPECT_EQ(loaded->preset.compression[std::size_t(MapSlot::Color)]->mipFilter, MipFilter::Box)
      << "an unknown mip filter falls back to box";
  EXPECT_EQ(material.parameter(ParamId::Tiling), parameterSpec(ParamId::Tiling).maximum);
  EXPECT_EQ(material.parameter(ParamId::HeightScale), parameterSpec(ParamId::HeightScale).maximum);
  std::string all;
  for (const std::string& warning : loaded->warnings) {
    EXPECT_NE(warning.find("partial.relief"), std::string::npos) << warning;
    all += warning + "\n";
  }
  for (const char* mention : {"missing_normal.png", "warp-drive", "tiling", "specular", "bogus",
                              "heightScale", "normalYDown", "zip", "lanczos9", "view.camera.pitch",
                              "view.camera.distance", "view.light.color", "view.display.exposure",
                              "filmic", "view.environment.intensity", "starfield"}) {
    EXPECT_NE(all.find(mention), std::string::npos) << mention << " not in:\n" << all;
  }
}

TEST(MaterialPreset, VersionOneMigrates) {
  const std::string folder = freshFolder("migrate");
  const std::string path = folder + "/old.relief";
  writeText(path,
            "{\"format\": \"relief-material\", \"version\": 1, \"name\": \"old\","
            " \"technique\": \"normal\", \"maps\": {},"
            " \"parameters\": {\"tiling\": 2, \"specular\": 0.5}}");
  Result<LoadedPreset> loaded = loadPreset(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_EQ(loaded->fileVersion, 1);
  EXPECT_TRUE(loaded->warnings.empty());
  EXPECT_EQ(loaded->preset.material.parameter(ParamId::Tiling), 2.0);
  ASSERT_TRUE(savePreset(loaded->preset, path).ok());
  const QJsonObject saved =
      QJsonDocument::fromJson(QByteArray::fromStdString(readText(path))).object();
  EXPECT_EQ(saved.value(QStringLiteral("version")).toInt(), kPresetVersion);
  EXPECT_EQ(saved.value(QStringLiteral("parameters"))
                .toObject()
                .value(QStringLiteral("specular"))
                .toDouble(),
            0.5);
}

// Version 2's default shading was classic: a version 2 file that does not name one keeps
// classic, and gets the roughness whose GGX lobe has its Blinn-Phong highlight's width,
// alpha^2 = 2 / (n + 2) (Walter et al. 2007): n = 62 gives alpha^2 = 1/32, roughness
// 32^-0.25 = 0.420. A file that names both keeps them.
TEST(MaterialPreset, VersionTwoKeepsClassicShadingAndGainsAMatchingRoughness) {
  const std::string folder = freshFolder("migrate2");
  const std::string path = folder + "/old.relief";
  writeText(path,
            "{\"format\": \"relief-material\", \"version\": 2, \"name\": \"old\","
            " \"technique\": \"pom\", \"maps\": {},"
            " \"parameters\": {\"shininess\": 62, \"specular\": 0.5}}");
  Result<LoadedPreset> loaded = loadPreset(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_EQ(loaded->fileVersion, 2);
  EXPECT_TRUE(loaded->warnings.empty());
  const Material& material = loaded->preset.material;
  EXPECT_EQ(material.parameter(ParamId::Shading), double(ShadingModel::Classic));
  EXPECT_NEAR(material.parameter(ParamId::Roughness), std::pow(32.0, -0.25), 1e-3);
  EXPECT_EQ(material.parameter(ParamId::Specular), 0.5);

  writeText(path,
            "{\"format\": \"relief-material\", \"version\": 2, \"technique\": \"pom\","
            " \"maps\": {}, \"parameters\": {\"shading\": \"pbr\", \"roughness\": 0.25}}");
  loaded = loadPreset(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_EQ(loaded->preset.material.parameter(ParamId::Shading), double(ShadingModel::Pbr));
  EXPECT_EQ(loaded->preset.material.parameter(ParamId::Roughness), 0.25);

  // A new material shades pbr.
  EXPECT_EQ(Material().parameter(ParamId::Shading), double(ShadingModel::Pbr));
}

TEST(MaterialPreset, AFailedSaveLeavesThePreviousFileByteForByte) {
  const std::string folder = freshFolder("atomic");
  const std::string path = folder + "/keep.relief";
  Result<LoadedPreset> sample = loadPreset(samplePreset("bricks"));
  ASSERT_TRUE(sample.ok());
  Preset preset = sample->preset;
  ASSERT_TRUE(savePreset(preset, path).ok());
  const std::string before = readText(path);

  // Make every write beyond 64 bytes fail (as a full disk would), then try to save a changed
  // preset. Works for root too, where folder permissions would not stop the write.
  preset.material.setParameter(ParamId::Tiling, 7.0);
  rlimit original{};
  getrlimit(RLIMIT_FSIZE, &original);
  const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit tiny = original;
  tiny.rlim_cur = 64;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &tiny), 0);
  Result<SavedPreset> saved = savePreset(preset, path);
  setrlimit(RLIMIT_FSIZE, &original);
  std::signal(SIGXFSZ, previousHandler);

  ASSERT_FALSE(saved.ok());
  EXPECT_NE(saved.error().find("keep.relief"), std::string::npos) << saved.error();
  EXPECT_EQ(readText(path), before);
  // And into a folder that does not exist: an error, no file.
  EXPECT_FALSE(savePreset(preset, folder + "/no/such/folder/x.relief").ok());
}

TEST(MaterialPreset, MapsMadeInTheEditorAreWrittenBesideThePreset) {
  const std::string folder = freshFolder("generated");
  Preset preset;
  preset.material.setName("made");
  auto height = std::make_shared<Image>(8, 4, 1);
  for (std::size_t i = 0; i < height->valueCount(); ++i)
    height->data()[i] = float(i) / 32.0f;
  auto deep = std::make_shared<Image>(8, 4, 1);
  deep->at(3, 1, 0) = 2.5f;  // beyond 0..1: needs EXR
  preset.material.setMap(MapSlot::Height, height);
  preset.material.setMap(MapSlot::AmbientOcclusion, deep);
  const std::string path = folder + "/made.relief";
  Result<SavedPreset> saved = savePreset(preset, path);
  ASSERT_TRUE(saved.ok()) << saved.error();
  ASSERT_EQ(saved->writtenMaps.size(), 2u);
  EXPECT_TRUE(std::filesystem::exists(folder + "/made_height.png"));
  EXPECT_TRUE(std::filesystem::exists(folder + "/made_ao.exr"));
  EXPECT_NE(readText(path).find("\"made_height.png\""), std::string::npos);  // relative
  Result<LoadedPreset> loaded = loadPreset(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  // 16-bit PNG: the values come back to 1/65535.
  const Image& back = *loaded->preset.material.image(MapSlot::Height);
  for (std::size_t i = 0; i < back.valueCount(); ++i) {
    EXPECT_NEAR(back.data()[i], height->data()[i], 1.0f / 65535.0f);
  }
  EXPECT_EQ(loaded->preset.material.image(MapSlot::AmbientOcclusion)->at(3, 1, 0), 2.5f);
}

// An ORM texture fills three slots from one file; the preset names the file once per slot
// with the channel it reads ("channel": "g"), writes no copies, and loads the same maps back.
// A channel that is no letter, or that the file lacks, is reported and that map skipped.
TEST(MaterialPreset, OrmChannelsRoundTripAsOneFileAndAChannelEach) {
  const std::string folder = freshFolder("orm");
  Image orm(8, 4, 3);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      orm.at(x, y, 0) = float(x) / 7.0f;
      orm.at(x, y, 1) = float(y) / 3.0f;
      orm.at(x, y, 2) = float((x + y) % 2);
    }
  }
  const std::string ormPath = folder + "/rock_orm.png";
  ASSERT_TRUE(saveImage(orm, ormPath, SampleFormat::UInt16).ok());
  Result<std::vector<ChannelMap>> maps = loadOrmTexture(ormPath);
  ASSERT_TRUE(maps.ok()) << maps.error();
  ASSERT_EQ(maps->size(), 3u);
  Preset preset;
  for (ChannelMap& map : maps.value()) {
    preset.material.setMap(map.slot, std::make_shared<Image>(std::move(map.image)), ormPath,
                           map.channel);
  }
  const std::string path = folder + "/rock.relief";
  Result<SavedPreset> saved = savePreset(preset, path);
  ASSERT_TRUE(saved.ok()) << saved.error();
  EXPECT_TRUE(saved->writtenMaps.empty());
  const QJsonObject written =
      QJsonDocument::fromJson(QByteArray::fromStdString(readText(path))).object();
  const QJsonObject mapsJson = written.value(QStringLiteral("maps")).toObject();
  const std::pair<const char*, const char*> expected[] = {
      {"ao", "r"}, {"roughness", "g"}, {"metallic", "b"}};
  for (const auto& [slot, letter] : expected) {
    const QJsonObject entry = mapsJson.value(QLatin1String(slot)).toObject();
    EXPECT_EQ(entry.value(QStringLiteral("path")).toString(), QStringLiteral("rock_orm.png"));
    EXPECT_EQ(entry.value(QStringLiteral("channel")).toString(), QLatin1String(letter)) << slot;
  }
  Result<LoadedPreset> loaded = loadPreset(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_TRUE(loaded->warnings.empty());
  const MapSlot slots[] = {MapSlot::AmbientOcclusion, MapSlot::Roughness, MapSlot::Metallic};
  for (int c = 0; c < 3; ++c) {
    const MaterialMap& map = loaded->preset.material.map(slots[c]);
    ASSERT_TRUE(map.image) << c;
    EXPECT_EQ(map.sourceChannel, c);
    ASSERT_EQ(map.image->channels(), 1);
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 8; ++x)
        EXPECT_NEAR(map.image->at(x, y, 0), orm.at(x, y, c), 1.0f / 65535.0f) << c;
    }
  }

  std::string text = readText(path);
  text.replace(text.find("\"g\""), 3, "\"q\"");
  text.replace(text.find("\"b\""), 3, "\"a\"");
  writeText(path, text);
  Result<LoadedPreset> broken = loadPreset(path);
  ASSERT_TRUE(broken.ok()) << broken.error();
  EXPECT_FALSE(broken->preset.material.hasMap(MapSlot::Roughness));
  EXPECT_FALSE(broken->preset.material.hasMap(MapSlot::Metallic));
  EXPECT_TRUE(broken->preset.material.hasMap(MapSlot::AmbientOcclusion));
  ASSERT_EQ(broken->warnings.size(), 2u);
  const std::string warnings = broken->warnings[0] + "\n" + broken->warnings[1];
  EXPECT_NE(warnings.find("roughness map: channel 'q'"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("metallic map: rock_orm.png has 3 channel(s), no 'a'"), std::string::npos)
      << warnings;

  // A grey file is no ORM texture; the message names it.
  ASSERT_TRUE(saveImage(Image(4, 4, 1), folder + "/grey_orm.png", SampleFormat::UInt8).ok());
  Result<std::vector<ChannelMap>> grey = loadOrmTexture(folder + "/grey_orm.png");
  ASSERT_FALSE(grey.ok());
  EXPECT_NE(grey.error().find("grey_orm.png"), std::string::npos) << grey.error();
}

TEST(MaterialPreset, TheDocumentedExampleLoadsWithoutWarnings) {
  // The first ```json block of docs/preset-format.md, beside copies of the bricks maps.
  const std::string doc = readText(test::sourcePath("docs/preset-format.md"));
  const std::size_t start = doc.find("```json\n");
  ASSERT_NE(start, std::string::npos);
  const std::size_t end = doc.find("```", start + 8);
  const std::string folder = freshFolder("documented");
  for (const char* slot : {"color", "normal", "height"}) {
    const std::string file = std::string("bricks_") + slot + ".png";
    std::filesystem::copy_file(test::sourcePath("samples/bricks/" + file), folder + "/" + file);
  }
  writeText(folder + "/example.relief", doc.substr(start + 8, end - start - 8));
  Result<LoadedPreset> loaded = loadPreset(folder + "/example.relief");
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  for (const std::string& warning : loaded->warnings)
    ADD_FAILURE() << warning;
  const Preset& preset = loaded->preset;
  EXPECT_EQ(preset.material.technique(), Technique::Pom);
  ASSERT_TRUE(preset.compression[std::size_t(MapSlot::Normal)].has_value());
  EXPECT_EQ(preset.compression[std::size_t(MapSlot::Normal)]->format, TextureFormat::Bc5);
  ASSERT_TRUE(preset.view.light.has_value());
  EXPECT_FLOAT_EQ(preset.view.light->color.g, 0.97f);
  // Every parameter core declares is in the example, so the page cannot fall behind.
  for (const ParameterSpec& spec : allParameters()) {
    EXPECT_NE(doc.find("\"" + std::string(spec.name) + "\""), std::string::npos) << spec.name;
  }
  for (const TextureFormatInfo& format : allTextureFormats()) {
    EXPECT_NE(doc.find("`" + std::string(format.name) + "`"), std::string::npos) << format.name;
  }
}

}  // namespace
}  // namespace relief::core
