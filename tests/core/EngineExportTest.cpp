// The Unreal and Unity exports: every file read back, the packed textures checked texel by texel
// against the material's maps, the .mat's references resolved through the .meta files, and the
// parallax parameters checked against the offsets each engine's shader computes (URP's
// ParallaxOffset1Step, HDRP's ApplyPerPixelDisplacement, as docs/export.md quotes them). The
// Unreal import script runs against a recording stand-in for the editor's Python module.
#include "ExportFixtures.h"
#include "core/exporters/EngineConversion.h"
#include "core/exporters/UnityExport.h"
#include "core/exporters/UnrealExport.h"
#include "core/image/ImageIO.h"
#include "support/TestPaths.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QStandardPaths>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace relief::core {
namespace {

constexpr float kEightBit = 1.0f / 255 + 1e-6f;

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Image load(const std::string& path) {
  Result<Image> image = loadImage(path);
  EXPECT_TRUE(image.ok()) << image.error();
  return image.ok() ? std::move(image).value() : Image();
}

// The largest difference between channel `channel` of `packed` and `expected(x, y)`.
template <class Expected>
double worstTexel(const Image& packed, int channel, Expected expected) {
  double worst = 0.0;
  for (int y = 0; y < packed.height(); ++y) {
    for (int x = 0; x < packed.width(); ++x)
      worst = std::max(worst, std::abs(double(packed.at(x, y, channel)) - expected(x, y)));
  }
  return worst;
}

const double kRoughness = std::pow(0.5, 0.25);  // shininess 2 (syntheticPreset)

TEST(EngineConversion, MasksTakeTheMaterialsConstantRoughnessAndNeutralValues) {
  const Preset preset = syntheticPreset();
  const Image& ao = *preset.material.image(MapSlot::AmbientOcclusion);
  const std::optional<Image> orm = packEngineMasks(preset.material, "orm");
  ASSERT_TRUE(orm.has_value());
  EXPECT_EQ(orm->channels(), 3);
  EXPECT_LT(worstTexel(*orm, 0, [&](int x, int y) { return ao.at(x, y, 0); }), 1e-6);
  EXPECT_LT(worstTexel(*orm, 1, [](int, int) { return kRoughness; }), 1e-5);
  EXPECT_LT(worstTexel(*orm, 2, [](int, int) { return 0.0; }), 1e-6);
  Preset bare = preset;
  bare.material.setMap(MapSlot::AmbientOcclusion, nullptr);
  EXPECT_FALSE(packEngineMasks(bare.material, "orm").has_value());
}

// Under pbr shading the masks carry the metallic constant and the roughness factor baked into
// the roughness map (engines' mask maps have no factor).
TEST(EngineConversion, PbrMasksCarryMetallicAndTheRoughnessFactor) {
  Preset preset = syntheticPreset();
  preset.material.setParameter(ParamId::Shading, double(int(ShadingModel::Pbr)));
  preset.material.setParameter(ParamId::Metallic, 0.7);
  preset.material.setParameter(ParamId::Roughness, 0.4);
  std::optional<Image> orm = packEngineMasks(preset.material, "orm");
  ASSERT_TRUE(orm.has_value());
  EXPECT_LT(worstTexel(*orm, 1, [](int, int) { return 0.4; }), 1e-5);
  EXPECT_LT(worstTexel(*orm, 2, [](int, int) { return 0.7; }), 1e-5);
  auto roughness =
      std::make_shared<Image>(preset.material.image(MapSlot::AmbientOcclusion)->width(),
                              preset.material.image(MapSlot::AmbientOcclusion)->height(), 1);
  for (std::size_t i = 0; i < roughness->valueCount(); ++i)
    roughness->data()[i] = float(i % 7) / 6.0f;
  preset.material.setMap(MapSlot::Roughness, roughness);
  const std::optional<Image> mask = packEngineMasks(preset.material, "unity-mask");
  ASSERT_TRUE(mask.has_value());
  EXPECT_LT(worstTexel(*mask, 0, [](int, int) { return 0.7; }), 1e-5);
  EXPECT_LT(worstTexel(*mask, 3, [&](int x, int y) { return 1.0 - 0.4 * roughness->at(x, y, 0); }),
            1e-5);
  // A metallic map: factor x map in the ORM's blue and the mask's red.
  auto metallic = std::make_shared<Image>(roughness->width(), roughness->height(), 1);
  for (std::size_t i = 0; i < metallic->valueCount(); ++i)
    metallic->data()[i] = float(i % 3) / 2.0f;
  preset.material.setMap(MapSlot::Metallic, metallic);
  orm = packEngineMasks(preset.material, "orm");
  ASSERT_TRUE(orm.has_value());
  EXPECT_LT(worstTexel(*orm, 2, [&](int x, int y) { return 0.7 * metallic->at(x, y, 0); }), 1e-5);
  const std::optional<Image> metalMask = packEngineMasks(preset.material, "unity-mask");
  ASSERT_TRUE(metalMask.has_value());
  EXPECT_LT(worstTexel(*metalMask, 0, [&](int x, int y) { return 0.7 * metallic->at(x, y, 0); }),
            1e-5);
  // Maps of different sizes (an AO at half the roughness's resolution) pack at the larger
  // size rather than being dropped; a constant map stays that constant when resized.
  auto smallMetal = std::make_shared<Image>(metallic->width() / 2, metallic->height() / 2, 1);
  std::fill(smallMetal->data(), smallMetal->data() + smallMetal->valueCount(), 0.5f);
  preset.material.setMap(MapSlot::Metallic, smallMetal);
  orm = packEngineMasks(preset.material, "orm");
  ASSERT_TRUE(orm.has_value());
  EXPECT_EQ(orm->width(), roughness->width());
  EXPECT_LT(worstTexel(*orm, 2, [](int, int) { return 0.7 * 0.5; }), 1e-4);
}

TEST(EngineConversion, GuidsAreStableHexAndDistinct) {
  const std::string a = stableGuid("/x/bricks_Normal.png");
  EXPECT_EQ(a.size(), 32u);
  EXPECT_TRUE(QRegularExpression(QStringLiteral("^[0-9a-f]{32}$"))
                  .match(QString::fromStdString(a))
                  .hasMatch());
  EXPECT_EQ(a, stableGuid("/x/bricks_Normal.png"));
  EXPECT_NE(a, stableGuid("/x/bricks_Height.png"));
  EXPECT_NE(a.substr(16), stableGuid("/y/bricks_Normal.png").substr(16));
}

// A Unity .mat and the .meta files beside it, read back.
struct UnityMaterialFile {
  std::string shaderGuid;
  std::vector<std::string> keywords;
  std::map<std::string, std::string> textureFiles;  // property -> file, through the GUIDs
  std::map<std::string, std::string> scales;        // property -> "{x: .., y: ..}"
  std::map<std::string, double> floats;
};

std::map<std::string, std::string> metaGuids(const std::string& folder) {
  std::map<std::string, std::string> files;  // guid -> asset file
  static const QRegularExpression guidLine(QStringLiteral("^guid: ([0-9a-f]{32})$"),
                                           QRegularExpression::MultilineOption);
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string path = entry.path().string();
    if (entry.path().extension() != ".meta")
      continue;
    const QRegularExpressionMatch match = guidLine.match(QString::fromStdString(readText(path)));
    EXPECT_TRUE(match.hasMatch()) << path;
    const std::string asset = path.substr(0, path.size() - 5);
    EXPECT_TRUE(std::filesystem::exists(asset)) << asset;
    EXPECT_EQ(files.count(match.captured(1).toStdString()), 0u) << "GUID used twice";
    files[match.captured(1).toStdString()] = std::filesystem::path(asset).filename().string();
  }
  return files;
}

UnityMaterialFile readUnityMaterial(const std::string& matPath) {
  const std::string folder = std::filesystem::path(matPath).parent_path().string();
  const std::map<std::string, std::string> guids = metaGuids(folder);
  UnityMaterialFile mat;
  std::istringstream lines(readText(matPath));
  std::string line, section, property;
  static const QRegularExpression shader(
      QStringLiteral(R"(^  m_Shader: \{fileID: 4800000, guid: ([0-9a-f]{32}), type: 3\}$)"));
  static const QRegularExpression entry(QStringLiteral(R"(^    - (_\w+):\s*(.*)$)"));
  static const QRegularExpression texture(
      QStringLiteral(R"(^        m_Texture: \{fileID: 2800000, guid: ([0-9a-f]{32}), type: 3\}$)"));
  static const QRegularExpression scale(QStringLiteral(R"(^        m_Scale: (.*)$)"));
  while (std::getline(lines, line)) {
    const QString text = QString::fromStdString(line);
    if (QRegularExpressionMatch m = shader.match(text); m.hasMatch()) {
      mat.shaderGuid = m.captured(1).toStdString();
    } else if (line.rfind("  - _", 0) == 0 && section == "keywords") {
      mat.keywords.push_back(line.substr(4));
    } else if (line.rfind("  m_ValidKeywords:", 0) == 0) {
      section = "keywords";
    } else if (line.rfind("    m_TexEnvs:", 0) == 0 || line.rfind("    m_Floats:", 0) == 0 ||
               line.rfind("    m_Colors:", 0) == 0) {
      section = line.substr(4, line.size() - 5);
    } else if (QRegularExpressionMatch e = entry.match(text); e.hasMatch()) {
      property = e.captured(1).toStdString();
      if (section == "m_Floats")
        mat.floats[property] = std::stod(e.captured(2).toStdString());
    } else if (QRegularExpressionMatch t = texture.match(text); t.hasMatch()) {
      const std::string guid = t.captured(1).toStdString();
      EXPECT_TRUE(guids.count(guid)) << property << " references a GUID no .meta holds";
      mat.textureFiles[property] = guids.count(guid) ? guids.at(guid) : "";
    } else if (QRegularExpressionMatch s = scale.match(text); s.hasMatch()) {
      mat.scales[property] = s.captured(1).toStdString();
    } else if (line.rfind("  m_", 0) == 0 || line.rfind("    m_", 0) == 0) {
      section.clear();
    }
  }
  return mat;
}

bool hasKeyword(const UnityMaterialFile& mat, const std::string& keyword) {
  return std::find(mat.keywords.begin(), mat.keywords.end(), keyword) != mat.keywords.end();
}

std::string metaOf(const std::string& folder, const std::string& file) {
  return readText(folder + "/" + file + ".meta");
}

TEST(UnityExport, UrpMaterialReferencesItsTexturesPackedAsUrpReadsThem) {
  const Preset preset = syntheticPreset();
  const std::string folder = freshFolder("unity-urp");
  Result<EngineExportResult> exported = exportUnity(preset, folder, UnityPipeline::Urp);
  ASSERT_TRUE(exported.ok()) << exported.error();
  EXPECT_EQ(exported->mainPath, folder + "/test_brick.mat");
  const UnityMaterialFile mat = readUnityMaterial(exported->mainPath);
  EXPECT_EQ(mat.shaderGuid, "933532a4fcc9baf4fa0491de14d08ed7");  // Universal Render Pipeline/Lit
  for (const char* keyword :
       {"_NORMALMAP", "_METALLICSPECGLOSSMAP", "_OCCLUSIONMAP", "_PARALLAXMAP"})
    EXPECT_TRUE(hasKeyword(mat, keyword)) << keyword;
  EXPECT_EQ(mat.scales.at("_BaseMap"), "{x: 2, y: 2}");  // tiling
  EXPECT_NEAR(mat.floats.at("_BumpScale"), 0.8, 1e-9);
  EXPECT_EQ(mat.floats.at("_Smoothness"), 1.0);  // the map's alpha carries it
  EXPECT_TRUE(metaOf(folder, "test_brick.mat").find("mainObjectFileID: 2100000") !=
              std::string::npos);

  // Texel by texel: the metallic/smoothness map is R metallic 0, A 1 - roughness.
  const Image metallic = load(folder + "/" + mat.textureFiles.at("_MetallicGlossMap"));
  ASSERT_EQ(metallic.channels(), 4);
  EXPECT_LT(worstTexel(metallic, 0, [](int, int) { return 0.0; }), kEightBit);
  EXPECT_LT(worstTexel(metallic, 3, [](int, int) { return 1.0 - kRoughness; }), kEightBit);
  const Image& ao = *preset.material.image(MapSlot::AmbientOcclusion);
  const Image occlusion = load(folder + "/" + mat.textureFiles.at("_OcclusionMap"));
  // URP reads occlusion from green: a grey map has it there.
  EXPECT_LT(worstTexel(occlusion, occlusion.channels() > 1 ? 1 : 0,
                       [&](int x, int y) { return ao.at(x, y, 0); }),
            kEightBit);
  const Image normal = load(folder + "/" + mat.textureFiles.at("_BumpMap"));
  EXPECT_LT(worstTexel(normal, 1, [](int, int) { return 0.75; }), kEightBit);  // OpenGL, +Y up
  const Image& relief = *preset.material.image(MapSlot::Height);
  const Image height = load(folder + "/" + mat.textureFiles.at("_ParallaxMap"));
  EXPECT_LT(worstTexel(height, 0, [&](int x, int y) { return relief.at(x, y, 0); }),
            1.0 / 65535 + 1e-6);
  EXPECT_EQ(mat.textureFiles.at("_BaseMap"), mat.textureFiles.at("_MainTex"));

  // Import settings: colour in sRGB, data linear, the normal map typed as one, nothing shrunk
  // to Unity's default 2048 limit below the image size.
  EXPECT_NE(metaOf(folder, mat.textureFiles.at("_BaseMap")).find("sRGBTexture: 1"),
            std::string::npos);
  const std::string normalMeta = metaOf(folder, mat.textureFiles.at("_BumpMap"));
  EXPECT_NE(normalMeta.find("sRGBTexture: 0"), std::string::npos);
  EXPECT_NE(normalMeta.find("textureType: 1"), std::string::npos);
  EXPECT_NE(metaOf(folder, mat.textureFiles.at("_ParallaxMap")).find("textureCompression: 0"),
            std::string::npos);  // 16-bit heights stay uncompressed

  // URP's ParallaxOffset1Step: (h A - A/2) v.xy / (v.z + 0.42). With Relief's bias at
  // -scale/2 (URP's reference plane) the two agree head-on within 0.1 %.
  const double amplitude = mat.floats.at("_Parallax");
  const double vx = 0.02, vz = std::sqrt(1 - vx * vx), h = 0.9;
  const double urp = (h * amplitude - amplitude / 2) * vx / (vz + 0.42);
  const double reliefOffset = (h * 0.06 - 0.03) * vx / vz;
  EXPECT_NEAR(urp, reliefOffset, 1e-3 * std::abs(reliefOffset));
  EXPECT_GE(exported->notes.size(), 2u);  // the reference plane and single-step parallax
}

TEST(UnityExport, HdrpMaskMapAndPixelDisplacementMatchReliefsOffsetAtEveryAngle) {
  Preset preset = syntheticPreset();
  preset.material.setParameter(ParamId::HeightIsDepth, 1.0);
  const std::string folder = freshFolder("unity-hdrp");
  Result<EngineExportResult> exported = exportUnity(preset, folder, UnityPipeline::Hdrp);
  ASSERT_TRUE(exported.ok()) << exported.error();
  const UnityMaterialFile mat = readUnityMaterial(exported->mainPath);
  EXPECT_EQ(mat.shaderGuid, "6e4ae4064600d784cac1e41a9e6f2e59");  // HDRP/Lit
  for (const char* keyword :
       {"_NORMALMAP", "_NORMALMAP_TANGENT_SPACE", "_MASKMAP", "_HEIGHTMAP", "_PIXEL_DISPLACEMENT"})
    EXPECT_TRUE(hasKeyword(mat, keyword)) << keyword;

  // The mask map: R metallic 0, G occlusion, B detail mask 1, A smoothness.
  const Image& ao = *preset.material.image(MapSlot::AmbientOcclusion);
  const Image mask = load(folder + "/" + mat.textureFiles.at("_MaskMap"));
  ASSERT_EQ(mask.channels(), 4);
  EXPECT_LT(worstTexel(mask, 0, [](int, int) { return 0.0; }), kEightBit);
  EXPECT_LT(worstTexel(mask, 1, [&](int x, int y) { return ao.at(x, y, 0); }), kEightBit);
  EXPECT_LT(worstTexel(mask, 2, [](int, int) { return 1.0; }), kEightBit);
  EXPECT_LT(worstTexel(mask, 3, [](int, int) { return 1.0 - kRoughness; }), kEightBit);
  // A depth map is inverted: HDRP reads white as the top.
  const Image& relief = *preset.material.image(MapSlot::Height);
  const Image height = load(folder + "/" + mat.textureFiles.at("_HeightMap"));
  EXPECT_LT(worstTexel(height, 0, [&](int x, int y) { return 1.0 - relief.at(x, y, 0); }),
            1.0 / 65535 + 1e-6);

  EXPECT_EQ(mat.floats.at("_DisplacementMode"), 2.0);
  EXPECT_EQ(mat.floats.at("_PPDMinSamples"), 12.0);
  EXPECT_EQ(mat.floats.at("_PPDMaxSamples"), 48.0);
  EXPECT_EQ(mat.floats.at("_HeightCenter"), 1.0);
  EXPECT_NEAR(mat.floats.at("_HeightAmplitude"), mat.floats.at("_HeightPoMAmplitude") * 0.01,
              1e-12);

  // HDRP's ApplyPerPixelDisplacement: maxHeight = amplitude / tiling (lock tiling scale),
  // uvSpaceScale = tiling * maxHeight / primitive, viewDirUV = (v.xy * uvSpaceScale, v.z), and
  // POM's full-depth offset viewDirUV.xy / viewDirUV.z. Relief's is v.xy / v.z * heightScale.
  const double tiling = 2.0;
  const double maxHeight = mat.floats.at("_HeightAmplitude") / tiling;
  const double uvSpaceScale = tiling * maxHeight / mat.floats.at("_PPDPrimitiveLength");
  for (double degrees : {0.5, 30.0, 70.0, 85.0}) {
    const double vx = std::sin(degrees * M_PI / 180), vz = std::cos(degrees * M_PI / 180);
    EXPECT_NEAR(vx * uvSpaceScale / vz, vx / vz * 0.06, 1e-9) << degrees << " degrees";
  }
}

TEST(UnrealExport, TexturesManifestAndScriptWireEpicsPomFunction) {
  const Preset preset = syntheticPreset();
  const std::string folder = freshFolder("unreal");
  Result<EngineExportResult> exported = exportUnreal(preset, folder);
  ASSERT_TRUE(exported.ok()) << exported.error();
  QFile file(QString::fromStdString(exported->mainPath));
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  const QJsonObject manifest = QJsonDocument::fromJson(file.readAll()).object();
  EXPECT_EQ(manifest.value(QStringLiteral("material")).toString(), QStringLiteral("M_test_brick"));
  const QJsonObject textures = manifest.value(QStringLiteral("textures")).toObject();
  const auto path = [&](const char* key) {
    return folder + "/" +
           textures.value(QLatin1String(key))
               .toObject()
               .value(QStringLiteral("file"))
               .toString()
               .toStdString();
  };
  EXPECT_EQ(textures.value(QStringLiteral("Normal"))
                .toObject()
                .value(QStringLiteral("compression"))
                .toString(),
            QStringLiteral("TC_NORMALMAP"));
  EXPECT_FALSE(
      textures.value(QStringLiteral("ORM")).toObject().value(QStringLiteral("srgb")).toBool(true));
  EXPECT_TRUE(textures.value(QStringLiteral("BaseColor"))
                  .toObject()
                  .value(QStringLiteral("srgb"))
                  .toBool());

  // The normal map stays DirectX (the source is green-down already), the ORM packs R AO,
  // G roughness, B metallic.
  EXPECT_EQ(path("Normal"), folder + "/T_test_brick_Normal.png");
  EXPECT_LT(worstTexel(load(path("Normal")), 1, [](int, int) { return 0.25; }), kEightBit);
  const Image& ao = *preset.material.image(MapSlot::AmbientOcclusion);
  const Image orm = load(path("ORM"));
  EXPECT_LT(worstTexel(orm, 0, [&](int x, int y) { return ao.at(x, y, 0); }), kEightBit);
  EXPECT_LT(worstTexel(orm, 1, [](int, int) { return kRoughness; }), kEightBit);
  EXPECT_LT(worstTexel(orm, 2, [](int, int) { return 0.0; }), kEightBit);
  Result<ImageFileInfo> height = readImageInfo(path("Height"));
  ASSERT_TRUE(height.ok()) << height.error();
  EXPECT_EQ(height->bitsPerChannel, 16);

  const QJsonObject parallax = manifest.value(QStringLiteral("parallax")).toObject();
  EXPECT_DOUBLE_EQ(parallax.value(QStringLiteral("HeightRatio")).toDouble(), 0.06);
  EXPECT_DOUBLE_EQ(parallax.value(QStringLiteral("ReferencePlane")).toDouble(),
                   1.0);  // top on the surface
  EXPECT_EQ(parallax.value(QStringLiteral("MinSteps")).toDouble(), 12.0);
  EXPECT_EQ(parallax.value(QStringLiteral("MaxSteps")).toDouble(), 48.0);
  EXPECT_DOUBLE_EQ(unrealReferencePlane(0.06, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(unrealReferencePlane(0.06, -0.03), 0.5);

  // The script runs against a recording stand-in for `unreal` and wires what the manifest says.
  const QString python = QStandardPaths::findExecutable(QStringLiteral("python3"));
  ASSERT_FALSE(python.isEmpty()) << "python3 is needed to run the Unreal script";
  const std::string log = folder + "/unreal-log.json";
  QProcess process;
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.insert(QStringLiteral("PYTHONPATH"),
                     QString::fromStdString(test::sourcePath("tests/core/fake_unreal")));
  environment.insert(QStringLiteral("RELIEF_FAKE_UNREAL_LOG"), QString::fromStdString(log));
  environment.insert(QStringLiteral("PYTHONDONTWRITEBYTECODE"), QStringLiteral("1"));
  process.setProcessEnvironment(environment);
  process.start(python, {QString::fromStdString(folder + "/test_brick_unreal_import.py")});
  ASSERT_TRUE(process.waitForFinished(60000));
  ASSERT_EQ(process.exitCode(), 0) << process.readAllStandardError().toStdString();
  QFile logFile(QString::fromStdString(log));
  ASSERT_TRUE(logFile.open(QIODevice::ReadOnly)) << "the script did not save the material";
  const QJsonObject record = QJsonDocument::fromJson(logFile.readAll()).object();
  EXPECT_EQ(record.value(QStringLiteral("imports")).toArray().size(), 4);
  const QJsonObject normalSettings = record.value(QStringLiteral("textures"))
                                         .toObject()
                                         .value(QStringLiteral("T_test_brick_Normal.png"))
                                         .toObject();
  EXPECT_EQ(normalSettings.value(QStringLiteral("compression_settings")).toString(),
            QStringLiteral("TC_NORMALMAP"));
  EXPECT_FALSE(normalSettings.value(QStringLiteral("srgb")).toBool(true));
  std::vector<std::string> links, properties;
  for (const QJsonValue& link : record.value(QStringLiteral("links")).toArray())
    links.push_back(link.toArray().at(1).toString().toStdString() + " -> " +
                    link.toArray().at(3).toString().toStdString());
  for (const QJsonValue& p : record.value(QStringLiteral("properties")).toArray())
    properties.push_back(p.toArray().at(1).toString().toStdString() + " -> " +
                         p.toArray().at(2).toString().toStdString());
  const auto has = [](const std::vector<std::string>& list, const std::string& item) {
    return std::find(list.begin(), list.end(), item) != list.end();
  };
  for (const char* input : {" -> Heightmap Texture", " -> UVs", " -> Height Ratio", " -> Min Steps",
                            " -> Max Steps", " -> Reference Plane", " -> Heightmap Channel"})
    EXPECT_TRUE(has(links, input)) << input;
  EXPECT_EQ(std::count(links.begin(), links.end(), "Parallax UVs -> UVs"), 3);  // every texture
  for (const char* wire : {"RGB -> MP_BASE_COLOR", "RGB -> MP_NORMAL", "R -> MP_AMBIENT_OCCLUSION",
                           "G -> MP_ROUGHNESS", "B -> MP_METALLIC"})
    EXPECT_TRUE(has(properties, wire)) << wire;
}

// The engine preview modes trace the values the exports write: each engine's preview parameters
// (core/exporters/EnginePreview.h) recomputed from the exported file by the engine's own unit
// rules, for a marching and a single-step technique.
TEST(EnginePreview, UnrealPreviewTracesTheManifestsPomInputs) {
  for (Technique technique : {Technique::Pom, Technique::ParallaxLimited}) {
    Preset preset = syntheticPreset();
    preset.material.setTechnique(technique);
    preset.material.setParameter(ParamId::HeightBias,
                                 -0.7 * preset.material.parameter(ParamId::HeightScale));
    const std::string folder = freshFolder("unreal-preview");
    Result<EngineExportResult> exported = exportUnreal(preset, folder);
    ASSERT_TRUE(exported.ok()) << exported.error();
    QFile file(QString::fromStdString(exported->mainPath));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QJsonObject pom = QJsonDocument::fromJson(file.readAll())
                                .object()
                                .value(QStringLiteral("parallax"))
                                .toObject();
    const EngineTraceParams trace = engineTrace(preset.material, Engine::Unreal);
    EXPECT_EQ(trace.trace, EngineTrace::UnrealPom);
    EXPECT_DOUBLE_EQ(trace.depth, pom.value(QStringLiteral("HeightRatio")).toDouble());
    EXPECT_DOUBLE_EQ(trace.minSteps, pom.value(QStringLiteral("MinSteps")).toDouble());
    EXPECT_DOUBLE_EQ(trace.maxSteps, pom.value(QStringLiteral("MaxSteps")).toDouble());
    EXPECT_DOUBLE_EQ(trace.referencePlane, pom.value(QStringLiteral("ReferencePlane")).toDouble());
    EXPECT_NEAR(trace.referencePlane, 0.7, 1e-12);
  }
}

TEST(EnginePreview, UnityPreviewsTraceTheMaterialsParallaxProperties) {
  for (Technique technique : {Technique::Pom, Technique::ParallaxLimited}) {
    Preset preset = syntheticPreset();
    preset.material.setTechnique(technique);
    preset.material.setParameter(ParamId::MaxSamples, 40);
    const std::string urpFolder = freshFolder("unity-urp-preview");
    Result<EngineExportResult> urp = exportUnity(preset, urpFolder, UnityPipeline::Urp);
    ASSERT_TRUE(urp.ok()) << urp.error();
    const UnityMaterialFile urpMat = readUnityMaterial(urp->mainPath);
    const EngineTraceParams urpTrace = engineTrace(preset.material, Engine::Unity);
    EXPECT_EQ(urpTrace.trace, EngineTrace::UrpOffset);
    EXPECT_DOUBLE_EQ(urpTrace.depth, urpMat.floats.at("_Parallax"));

    const std::string hdrpFolder = freshFolder("unity-hdrp-preview");
    Result<EngineExportResult> hdrp = exportUnity(preset, hdrpFolder, UnityPipeline::Hdrp);
    ASSERT_TRUE(hdrp.ok()) << hdrp.error();
    const UnityMaterialFile mat = readUnityMaterial(hdrp->mainPath);
    const EngineTraceParams trace = engineTrace(preset.material, Engine::UnityHdrp);
    EXPECT_EQ(trace.trace, EngineTrace::HdrpPom);
    // HDRP's uvSpaceScale with the tiling scale locked: amplitude (cm to m) over the primitive.
    ASSERT_EQ(mat.floats.at("_DisplacementLockTilingScale"), 1.0);
    EXPECT_NEAR(trace.depth,
                mat.floats.at("_HeightPoMAmplitude") * 0.01 / mat.floats.at("_PPDPrimitiveLength"),
                1e-12);
    EXPECT_DOUBLE_EQ(trace.minSteps, mat.floats.at("_PPDMinSamples"));
    EXPECT_DOUBLE_EQ(trace.maxSteps, mat.floats.at("_PPDMaxSamples"));
    EXPECT_DOUBLE_EQ(trace.lodThreshold, mat.floats.at("_PPDLodThreshold"));
  }
}

// Self-shadowing: no exported engine material has it; the export says so when the material
// shadows, and the preview draws without it (tests/renderer/EnginePreviewTest.cpp).
TEST(EnginePreview, ExportsSayTheSelfShadowingIsLost) {
  Preset preset = syntheticPreset();
  preset.material.setParameter(ParamId::ShadowMode, double(ShadowMode::Hard));
  const auto mentionsShadows = [](const std::vector<std::string>& notes) {
    return std::any_of(notes.begin(), notes.end(), [](const std::string& note) {
      return note.find("self-shadowing is lost") != std::string::npos;
    });
  };
  Result<EngineExportResult> unreal = exportUnreal(preset, freshFolder("unreal-shadows"));
  Result<EngineExportResult> urp =
      exportUnity(preset, freshFolder("urp-shadows"), UnityPipeline::Urp);
  ASSERT_TRUE(unreal.ok() && urp.ok());
  EXPECT_TRUE(mentionsShadows(unreal->notes));
  EXPECT_TRUE(mentionsShadows(urp->notes));
  preset.material.setParameter(ParamId::ShadowMode, double(ShadowMode::Off));
  Result<EngineExportResult> quiet = exportUnreal(preset, freshFolder("unreal-no-shadows"));
  ASSERT_TRUE(quiet.ok());
  EXPECT_FALSE(mentionsShadows(quiet->notes));
}

}  // namespace
}  // namespace relief::core
