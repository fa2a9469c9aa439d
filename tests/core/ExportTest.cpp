// Export: a package reloads as the same material; the glTF export is read back field by field
// against the glTF 2.0 specification and passed through the Khronos validator; the Godot
// .tres is parsed back and its heightmap settings checked against the offset Godot 4's
// generated shader computes (docs/export.md).
#include "ExportFixtures.h"
#include "core/compression/TextureFile.h"
#include "core/exporters/EngineConversion.h"
#include "core/exporters/EnginePreview.h"
#include "core/exporters/GltfExport.h"
#include "core/exporters/GodotExport.h"
#include "core/exporters/PackageExport.h"
#include "core/image/ImageIO.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "core/shading/Brdf.h"
#include "support/GltfValidator.h"
#include "support/TestPaths.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

namespace relief::core {
namespace {

double maxDifference(const Image& a, const Image& b) {
  EXPECT_EQ(a.width(), b.width());
  EXPECT_EQ(a.height(), b.height());
  EXPECT_EQ(a.channels(), b.channels());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.valueCount(), b.valueCount()); ++i)
    worst = std::max(worst, double(std::abs(a.data()[i] - b.data()[i])));
  return worst;
}

TEST(EngineConversion, RoughnessMatchesBlinnPhongLobeWidth) {
  // alpha^2 = 2 / (n + 2) and alpha = r^2 (Walter et al. 2007; glTF's perceptual roughness).
  EXPECT_DOUBLE_EQ(roughnessFromShininess(0.0), 1.0);
  EXPECT_NEAR(roughnessFromShininess(2.0), std::pow(0.5, 0.25), 1e-12);
  EXPECT_NEAR(roughnessFromShininess(198.0), std::pow(0.01, 0.25), 1e-12);
  EXPECT_LT(roughnessFromShininess(1000.0), roughnessFromShininess(100.0));
}

TEST(EngineConversion, DirectXNormalMapsBecomeOpenGL) {
  Image normal(1, 1, 3);
  normal.at(0, 0, 1) = 0.2f;
  EXPECT_FLOAT_EQ(openGlNormalMap(normal, true).at(0, 0, 1), 0.8f);
  EXPECT_FLOAT_EQ(openGlNormalMap(normal, false).at(0, 0, 1), 0.2f);
}

TEST(PackageExport, ReloadsAsTheSameMaterial) {
  const Preset preset = syntheticPreset();
  for (PackageMapFormat format :
       {PackageMapFormat::Png8, PackageMapFormat::Png16, PackageMapFormat::Exr}) {
    const std::string folder = freshFolder("package" + std::to_string(int(format)));
    Result<std::string> exported = exportPackage(preset, folder, {format});
    ASSERT_TRUE(exported.ok()) << exported.error();
    EXPECT_EQ(std::filesystem::path(exported.value()).filename(), "test_brick.relief");
    Result<LoadedPreset> loaded = loadPreset(exported.value());
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_TRUE(loaded->warnings.empty());
    const Material& material = loaded->preset.material;
    EXPECT_EQ(material.parameters(), preset.material.parameters());
    EXPECT_EQ(material.technique(), Technique::Pom);
    // Quantisation bounds: half a step of the file's integer format; EXR keeps floats.
    const double dataTolerance = format == PackageMapFormat::Png8    ? 0.5 / 255 + 1e-6
                                 : format == PackageMapFormat::Png16 ? 0.5 / 65535 + 1e-7
                                                                     : 0.0;
    for (MapSlot slot : {MapSlot::Normal, MapSlot::Height, MapSlot::AmbientOcclusion}) {
      ASSERT_TRUE(material.hasMap(slot)) << mapSlotName(slot);
      // 8-bit data maps are dithered: one step at most.
      const double tolerance = format == PackageMapFormat::Png8 ? 1.0 / 255 + 1e-6 : dataTolerance;
      EXPECT_LE(maxDifference(*material.image(slot), *preset.material.image(slot)), tolerance)
          << mapSlotName(slot) << " format " << int(format);
      // The preset names the file beside it, relative.
      EXPECT_EQ(std::filesystem::path(material.map(slot).sourcePath).parent_path(),
                std::filesystem::path(exported.value()).parent_path());
    }
    EXPECT_LE(
        maxDifference(*material.image(MapSlot::Color), *preset.material.image(MapSlot::Color)),
        0.5 / 255 + 1e-6);
    const std::string heightFile = material.map(MapSlot::Height).sourcePath;
    EXPECT_EQ(std::filesystem::path(heightFile).extension(),
              format == PackageMapFormat::Exr ? ".exr" : ".png");
  }
}

TEST(PackageExport, MapsWithACompressionChoiceAreAlsoWrittenCompressed) {
  Preset preset = syntheticPreset();
  preset.compression[std::size_t(MapSlot::Color)] =
      CompressionSettings{TextureFormat::Astc6x6, CompressionQuality::Fast, true, 5};
  preset.compression[std::size_t(MapSlot::Normal)] =
      CompressionSettings{TextureFormat::Bc5, CompressionQuality::Normal, true, 5};
  preset.compression[std::size_t(MapSlot::Height)] =
      CompressionSettings{TextureFormat::Bc4, CompressionQuality::Normal, false};
  for (PackageTextures textures : {PackageTextures::Ktx2, PackageTextures::DdsWherePossible}) {
    const std::string folder = freshFolder("compressed" + std::to_string(int(textures)));
    ASSERT_TRUE(exportPackage(preset, folder, {PackageMapFormat::Png16, textures}).ok());
    const bool dds = textures == PackageTextures::DdsWherePossible;
    // ASTC has no DDS code, so it is KTX2 either way; BC goes to DDS when asked.
    const auto path = [&](const char* slot, bool bc) {
      return folder + "/test_brick_" + slot + (dds && bc ? ".dds" : ".ktx2");
    };
    Result<CompressedTexture> colour = loadCompressedTexture(path("color", false));
    Result<CompressedTexture> normal = loadCompressedTexture(path("normal", true));
    Result<CompressedTexture> height = loadCompressedTexture(path("height", true));
    ASSERT_TRUE(colour.ok()) << colour.error();
    ASSERT_TRUE(normal.ok()) << normal.error();
    ASSERT_TRUE(height.ok()) << height.error();
    EXPECT_EQ(colour->format, TextureFormat::Astc6x6);
    // The preset's Zstandard level applies to KTX2 files; DDS has no supercompression.
    EXPECT_TRUE(colour->zstdInFile);
    EXPECT_EQ(normal->zstdInFile, !dds);
    EXPECT_EQ(colour->levels.size(), 5u);  // 16x16 with mips
    EXPECT_EQ(normal->format, TextureFormat::Bc5);
    EXPECT_EQ(normal->slot, MapSlot::Normal);
    EXPECT_EQ(height->levels.size(), 1u);  // mipmaps: false
    // The AO map has no choice and no compressed file; the preset still names the PNGs.
    EXPECT_FALSE(std::filesystem::exists(folder + "/test_brick_ao.ktx2"));
    EXPECT_FALSE(std::filesystem::exists(folder + "/test_brick_ao.dds"));
  }
  const std::string none = freshFolder("uncompressed");
  ASSERT_TRUE(exportPackage(preset, none, {PackageMapFormat::Png16, PackageTextures::None}).ok());
  EXPECT_FALSE(std::filesystem::exists(none + "/test_brick_normal.ktx2"));
}

TEST(PackageExport, AFolderThatCannotBeMadeIsReportedByName) {
  // A file where the folder should go fails even for root, unlike permission bits.
  const std::string blocker = freshFolder("blocked") + "/not-a-folder";
  std::ofstream(blocker) << "x";
  Result<std::string> exported = exportPackage(syntheticPreset(), blocker + "/package");
  ASSERT_FALSE(exported.ok());
  EXPECT_NE(exported.error().find(blocker), std::string::npos) << exported.error();
}

QJsonObject readJson(const std::string& path) {
  QFile file(QString::fromStdString(path));
  EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path;
  return QJsonDocument::fromJson(file.readAll()).object();
}

std::vector<float> readFloats(const QJsonObject& gltf, const std::string& binary, int accessor) {
  const QJsonObject a = gltf["accessors"].toArray()[accessor].toObject();
  const QJsonObject view = gltf["bufferViews"].toArray()[a["bufferView"].toInt()].toObject();
  EXPECT_EQ(a["componentType"].toInt(), 5126);
  const int components = a["type"].toString() == "VEC2"   ? 2
                         : a["type"].toString() == "VEC3" ? 3
                         : a["type"].toString() == "VEC4" ? 4
                                                          : 1;
  const std::size_t count = std::size_t(a["count"].toInt()) * std::size_t(components);
  const std::size_t offset = std::size_t(view["byteOffset"].toInteger());
  EXPECT_EQ(offset % 4, 0u) << "glTF requires 4-byte aligned float accessors";
  EXPECT_EQ(std::size_t(view["byteLength"].toInteger()), count * sizeof(float));
  std::vector<float> values(count);
  std::memcpy(values.data(), binary.data() + offset, count * sizeof(float));
  return values;
}

TEST(GltfExport, MeshAndMaterialFollowTheSpecification) {
  const Preset preset = syntheticPreset();
  const Mesh plane = makePlane(2.0f, 2);
  const std::string folder = freshFolder("gltf");
  Result<std::string> exported = exportGltf(preset, plane, folder);
  ASSERT_TRUE(exported.ok()) << exported.error();
  const QJsonObject gltf = readJson(exported.value());
  EXPECT_EQ(gltf["asset"].toObject()["version"].toString(), "2.0");

  const QJsonObject buffer = gltf["buffers"].toArray()[0].toObject();
  const std::string binPath = folder + "/" + buffer["uri"].toString().toStdString();
  std::ifstream in(binPath, std::ios::binary);
  const std::string binary(std::istreambuf_iterator<char>(in), {});
  EXPECT_EQ(qint64(binary.size()), buffer["byteLength"].toInteger());

  const QJsonObject primitive =
      gltf["meshes"].toArray()[0].toObject()["primitives"].toArray()[0].toObject();
  const QJsonObject attributes = primitive["attributes"].toObject();
  const std::vector<float> positions = readFloats(gltf, binary, attributes["POSITION"].toInt());
  const std::vector<float> uvs = readFloats(gltf, binary, attributes["TEXCOORD_0"].toInt());
  const std::vector<float> tangents = readFloats(gltf, binary, attributes["TANGENT"].toInt());
  ASSERT_EQ(positions.size(), plane.vertices.size() * 3);
  for (std::size_t i = 0; i < plane.vertices.size(); ++i) {
    const Vertex& v = plane.vertices[i];
    EXPECT_FLOAT_EQ(positions[i * 3 + 0], v.position.x);
    // glTF's texture origin is the image's top-left: v flips; tiling 2 is baked in.
    EXPECT_FLOAT_EQ(uvs[i * 2 + 0], 2.0f * v.uv.x);
    EXPECT_FLOAT_EQ(uvs[i * 2 + 1], 1.0f - 2.0f * v.uv.y);
    EXPECT_EQ(std::abs(tangents[i * 4 + 3]), 1.0f) << "tangent w must be +-1";
  }
  const QJsonArray min =
      gltf["accessors"].toArray()[attributes["POSITION"].toInt()].toObject()["min"].toArray();
  EXPECT_FLOAT_EQ(float(min[0].toDouble()), -1.0f);

  const QJsonObject material = gltf["materials"].toArray()[0].toObject();
  const QJsonObject pbr = material["pbrMetallicRoughness"].toObject();
  EXPECT_DOUBLE_EQ(pbr["metallicFactor"].toDouble(), 0.0);
  EXPECT_NEAR(pbr["roughnessFactor"].toDouble(), std::pow(0.5, 0.25), 1e-9);
  EXPECT_NEAR(material["normalTexture"].toObject()["scale"].toDouble(), 0.8, 1e-9);

  // The normal texture is in glTF's +Y-up convention: the DirectX green 0.25 becomes 0.75.
  const QJsonArray images = gltf["images"].toArray();
  const QJsonArray textures = gltf["textures"].toArray();
  const auto imageOf = [&](const QJsonObject& textureInfo) {
    const int source = textures[textureInfo["index"].toInt()].toObject()["source"].toInt();
    return folder + "/" + images[source].toObject()["uri"].toString().toStdString();
  };
  Result<Image> normal = loadImage(imageOf(material["normalTexture"].toObject()));
  ASSERT_TRUE(normal.ok()) << normal.error();
  EXPECT_NEAR(normal->at(3, 3, 1), 0.75f, 1.0f / 255);
  Result<Image> color = loadImage(imageOf(pbr["baseColorTexture"].toObject()));
  ASSERT_TRUE(color.ok()) << color.error();
  EXPECT_EQ(color->colorSpace(), ColorSpace::Srgb);

  // Parallax lives in extras: every parameter by name and the height image.
  const QJsonObject relief = material["extras"].toObject()["relief"].toObject();
  EXPECT_EQ(relief["technique"].toString(), "pom");
  EXPECT_NEAR(relief["parameters"].toObject()["heightScale"].toDouble(), 0.06, 1e-12);
  EXPECT_EQ(relief["parameters"].toObject().size(), qsizetype(allParameters().size()));
  Result<Image> height = loadImage(folder + "/" + relief["heightImage"].toString().toStdString());
  ASSERT_TRUE(height.ok()) << height.error();
  EXPECT_LE(maxDifference(height.value(), *preset.material.image(MapSlot::Height)),
            0.5 / 65535 + 1e-7);
}

TEST(GltfExport, KhronosValidatorFindsNoErrors) {
  const std::string folder = freshFolder("gltf-validate");
  for (const char* shape : {"plane", "sphere", "torus"}) {
    Result<std::string> exported = exportGltf(
        syntheticPreset(), makePrimitive(*findPrimitiveShape(shape)), folder + "/" + shape);
    ASSERT_TRUE(exported.ok()) << exported.error();
    const test::GltfValidation validation = test::validateGltf(exported.value());
    if (!validation.available)
      GTEST_SKIP() << "glTF validator unavailable: " << validation.unavailableReason;
    EXPECT_EQ(validation.errors, 0) << shape << "\n" << validation.report;
    // Warnings are allowed by the issue, but the export should not produce any either.
    EXPECT_EQ(validation.warnings, 0) << shape << "\n" << validation.report;
  }
  // Control: the validator, as wired here, does report a broken file (a buffer longer than its
  // .bin), so the zero above means something.
  const std::string broken = folder + "/plane/broken.gltf";
  QJsonObject gltf = readJson(folder + "/plane/test_brick.gltf");
  QJsonArray buffers = gltf["buffers"].toArray();
  QJsonObject buffer = buffers[0].toObject();
  buffer["byteLength"] = buffer["byteLength"].toInteger() + 64;
  buffers[0] = buffer;
  gltf["buffers"] = buffers;
  QFile file(QString::fromStdString(broken));
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write(QJsonDocument(gltf).toJson());
  file.close();
  EXPECT_GT(test::validateGltf(broken).errors, 0);
}

TEST(GltfExport, AnEmptyMeshIsRefused) {
  Result<std::string> exported = exportGltf(syntheticPreset(), Mesh{}, freshFolder("empty"));
  ASSERT_FALSE(exported.ok());
  EXPECT_NE(exported.error().find("empty"), std::string::npos);
}

// A reader for Godot's text resource format, written from the format's documentation: section
// headers in brackets with key=value attributes, then `key = value` property lines.
struct GodotResource {
  std::map<std::string, std::string> header;
  std::vector<std::map<std::string, std::string>> extResources;
  std::map<std::string, std::string> properties;
};

// std::regex would do, but GCC 12 warns falsely inside it at -O2 (-Wmaybe-uninitialized).
std::map<std::string, std::string> parseAttributes(const QString& text) {
  std::map<std::string, std::string> attributes;
  static const QRegularExpression attribute(QStringLiteral(R"re((\w+)=("[^"]*"|\S+))re"));
  for (const QRegularExpressionMatch& match : attribute.globalMatch(text)) {
    QString value = match.captured(2);
    if (value.size() >= 2 && value.front() == QLatin1Char('"'))
      value = value.mid(1, value.size() - 2);
    attributes[match.captured(1).toStdString()] = value.toStdString();
  }
  return attributes;
}

GodotResource parseTres(const std::string& path) {
  GodotResource resource;
  std::ifstream in(path);
  std::string line, section;
  static const QRegularExpression header(QStringLiteral(R"re(^\[(\w+)(.*)\]$)re"));
  static const QRegularExpression property(QStringLiteral(R"re(^(\w+) = (.+)$)re"));
  while (std::getline(in, line)) {
    const QString text = QString::fromStdString(line);
    if (const QRegularExpressionMatch match = header.match(text); match.hasMatch()) {
      section = match.captured(1).toStdString();
      if (section == "gd_resource")
        resource.header = parseAttributes(match.captured(2));
      else if (section == "ext_resource")
        resource.extResources.push_back(parseAttributes(match.captured(2)));
    } else if (const QRegularExpressionMatch prop = property.match(text);
               section == "resource" && prop.hasMatch()) {
      resource.properties[prop.captured(1).toStdString()] = prop.captured(2).toStdString();
    } else {
      EXPECT_TRUE(line.empty()) << "unexpected line in " << path << ": " << line;
    }
  }
  return resource;
}

// Godot 4's generated StandardMaterial3D shader (scene/resources/material.cpp) offsets the
// texture coordinates by view.xy * depth * heightmap_scale * 0.01, depth = 1 - h (or h when
// heightmap_flip_texture). Relief's surface lies s = h * scale + bias above the mesh, so with
// bias = -scale a point of depth d = 1 - h lies d * scale below it and is seen
// view.xy / view.z * d * scale away (references 000, 001). The two agree head-on (view.z -> 1).
TEST(GodotExport, TresParsesBackWithHeightmapSettingsConverted) {
  const Preset preset = syntheticPreset();
  const std::string folder = freshFolder("godot");
  Result<EngineExportResult> exported = exportGodot(preset, folder);
  ASSERT_TRUE(exported.ok()) << exported.error();
  const GodotResource tres = parseTres(exported->mainPath);
  EXPECT_EQ(tres.header.at("type"), "StandardMaterial3D");
  EXPECT_EQ(tres.header.at("format"), "3");
  EXPECT_EQ(std::stoi(tres.header.at("load_steps")), int(tres.extResources.size()) + 1);

  // Every ExtResource reference names a declared texture whose file exists beside the .tres.
  std::map<std::string, std::string> files;
  for (const auto& ext : tres.extResources) {
    EXPECT_EQ(ext.at("type"), "Texture2D");
    files[ext.at("id")] = ext.at("path");
    EXPECT_TRUE(std::filesystem::exists(folder + "/" + ext.at("path"))) << ext.at("path");
  }
  const auto texture = [&](const std::string& key) -> std::string {
    static const QRegularExpression reference(QStringLiteral(R"re(^ExtResource\("([^"]+)"\)$)re"));
    const std::string value = tres.properties.count(key) ? tres.properties.at(key) : "";
    const QRegularExpressionMatch m = reference.match(QString::fromStdString(value));
    if (!m.hasMatch())
      return "";
    const std::string id = m.captured(1).toStdString();
    EXPECT_TRUE(files.count(id)) << key << " references undeclared " << id;
    return files[id];
  };
  const auto& p = tres.properties;
  EXPECT_FALSE(texture("albedo_texture").empty());
  EXPECT_EQ(p.at("normal_enabled"), "true");
  EXPECT_NEAR(std::stod(p.at("normal_scale")), 0.8, 1e-6);
  EXPECT_EQ(p.at("ao_enabled"), "true");
  EXPECT_NEAR(std::stod(p.at("roughness")), std::pow(0.5, 0.25), 1e-5);
  EXPECT_EQ(p.at("heightmap_enabled"), "true");
  EXPECT_EQ(p.at("heightmap_deep_parallax"), "true");  // POM marches, as Godot's deep parallax
  EXPECT_EQ(p.at("heightmap_min_layers"), "12");
  EXPECT_EQ(p.at("heightmap_max_layers"), "48");
  EXPECT_EQ(p.at("heightmap_flip_texture"), "false");
  EXPECT_EQ(p.at("uv1_scale"), "Vector3(2.0, 2.0, 1.0)");

  // The parallax offset Godot computes matches Relief's head-on, within 0.1 %.
  const double godotScale = std::stod(p.at("heightmap_scale"));
  const double viewX = 0.02, viewZ = std::sqrt(1.0 - viewX * viewX);
  const double depth = 0.7;
  const double godotOffset = viewX * depth * godotScale * 0.01;
  const double reliefOffset = viewX / viewZ * depth * 0.06;
  EXPECT_NEAR(godotOffset, reliefOffset, 1e-3 * reliefOffset);

  // Normal map converted to Godot's OpenGL convention, height kept at 16 bits.
  Result<Image> normal = loadImage(folder + "/" + texture("normal_texture"));
  ASSERT_TRUE(normal.ok()) << normal.error();
  EXPECT_NEAR(normal->at(0, 0, 1), 0.75f, 1.0f / 255);
  Result<ImageFileInfo> height = readImageInfo(folder + "/" + texture("heightmap_texture"));
  ASSERT_TRUE(height.ok()) << height.error();
  EXPECT_EQ(height->bitsPerChannel, 16);
  EXPECT_TRUE(exported->notes.size() >= 1);  // Godot's offset-limited deep parallax
}

// Under pbr shading the exports carry the metallic and roughness the viewport shows, not the
// Blinn-Phong equivalent; with a roughness map, as factor x map (glTF and Godot multiply).
TEST(GltfExport, PbrShadingExportsItsMetallicAndRoughness) {
  Preset preset = syntheticPreset();
  preset.material.setParameter(ParamId::Shading, double(int(ShadingModel::Pbr)));
  preset.material.setParameter(ParamId::Metallic, 0.7);
  preset.material.setParameter(ParamId::Roughness, 0.35);
  Result<std::string> gltfPath = exportGltf(preset, makePlane(2.0f, 1), freshFolder("gltf-pbr"));
  ASSERT_TRUE(gltfPath.ok()) << gltfPath.error();
  const QJsonObject pbr = readJson(gltfPath.value())["materials"]
                              .toArray()[0]
                              .toObject()["pbrMetallicRoughness"]
                              .toObject();
  EXPECT_DOUBLE_EQ(pbr["metallicFactor"].toDouble(), 0.7);
  EXPECT_DOUBLE_EQ(pbr["roughnessFactor"].toDouble(), 0.35);

  Result<EngineExportResult> godot = exportGodot(preset, freshFolder("godot-pbr"));
  ASSERT_TRUE(godot.ok()) << godot.error();
  const GodotResource tres = parseTres(godot->mainPath);
  EXPECT_DOUBLE_EQ(std::stod(tres.properties.at("metallic")), 0.7);
  EXPECT_DOUBLE_EQ(std::stod(tres.properties.at("roughness")), 0.35);

  // A roughness map: the texture carries it (blue 1 lets metallicFactor through), the factor
  // multiplies it.
  auto roughnessMap = std::make_shared<Image>(4, 4, 1);
  for (int i = 0; i < 16; ++i)
    roughnessMap->data()[i] = float(i) / 15.0f;
  preset.material.setMap(MapSlot::Roughness, roughnessMap);
  const std::string folder = freshFolder("gltf-pbr-map");
  gltfPath = exportGltf(preset, makePlane(2.0f, 1), folder);
  ASSERT_TRUE(gltfPath.ok()) << gltfPath.error();
  const QJsonObject gltf = readJson(gltfPath.value());
  const QJsonObject withMap =
      gltf["materials"].toArray()[0].toObject()["pbrMetallicRoughness"].toObject();
  EXPECT_DOUBLE_EQ(withMap["roughnessFactor"].toDouble(), 0.35);
  const int texture = withMap["metallicRoughnessTexture"].toObject()["index"].toInt();
  const int source = gltf["textures"].toArray()[texture].toObject()["source"].toInt();
  Result<Image> packed = loadImage(
      folder + "/" + gltf["images"].toArray()[source].toObject()["uri"].toString().toStdString());
  ASSERT_TRUE(packed.ok()) << packed.error();
  for (int i = 0; i < 16; ++i) {
    EXPECT_NEAR(packed->at(i % 4, i / 4, 1), roughnessMap->data()[i], 0.5f / 255.0f);
    EXPECT_EQ(packed->at(i % 4, i / 4, 2), 1.0f);
  }
}

// A metallic map travels too: glTF's metallicRoughnessTexture carries it in blue beside the
// roughness in green (a missing roughness map is green 1, letting its factor through), and
// Godot's metallic_texture names a file that holds it; both engines multiply by the factor.
TEST(GltfExport, AMetallicMapGoesToBlueAndToGodotsMetallicTexture) {
  Preset preset = syntheticPreset();
  preset.material.setParameter(ParamId::Shading, double(int(ShadingModel::Pbr)));
  preset.material.setParameter(ParamId::Metallic, 0.9);
  auto metallicMap = std::make_shared<Image>(4, 4, 1);
  for (int i = 0; i < 16; ++i)
    metallicMap->data()[i] = float(i % 2);  // a checker of metal and dielectric
  preset.material.setMap(MapSlot::Metallic, metallicMap);
  const std::string folder = freshFolder("gltf-metallic-map");
  Result<std::string> gltfPath = exportGltf(preset, makePlane(2.0f, 1), folder);
  ASSERT_TRUE(gltfPath.ok()) << gltfPath.error();
  const QJsonObject gltf = readJson(gltfPath.value());
  const QJsonObject pbr =
      gltf["materials"].toArray()[0].toObject()["pbrMetallicRoughness"].toObject();
  EXPECT_DOUBLE_EQ(pbr["metallicFactor"].toDouble(), 0.9);
  const int texture = pbr["metallicRoughnessTexture"].toObject()["index"].toInt();
  const int source = gltf["textures"].toArray()[texture].toObject()["source"].toInt();
  Result<Image> packed = loadImage(
      folder + "/" + gltf["images"].toArray()[source].toObject()["uri"].toString().toStdString());
  ASSERT_TRUE(packed.ok()) << packed.error();
  for (int i = 0; i < 16; ++i) {
    EXPECT_EQ(packed->at(i % 4, i / 4, 1), 1.0f);
    EXPECT_EQ(packed->at(i % 4, i / 4, 2), metallicMap->data()[i]);
  }

  const std::string godotFolder = freshFolder("godot-metallic-map");
  Result<EngineExportResult> godot = exportGodot(preset, godotFolder);
  ASSERT_TRUE(godot.ok()) << godot.error();
  const GodotResource tres = parseTres(godot->mainPath);
  EXPECT_DOUBLE_EQ(std::stod(tres.properties.at("metallic")), 0.9);
  const std::string reference = tres.properties.at("metallic_texture");
  std::string file;
  for (const auto& ext : tres.extResources) {
    if (reference == "ExtResource(\"" + ext.at("id") + "\")")
      file = ext.at("path");
  }
  ASSERT_FALSE(file.empty()) << reference;
  Result<Image> metallic = loadImage(godotFolder + "/" + file);
  ASSERT_TRUE(metallic.ok()) << metallic.error();
  for (int i = 0; i < 16; ++i)
    EXPECT_EQ(metallic->at(i % 4, i / 4, 0), metallicMap->data()[i]);
  // A roughness map twice the size: the one texture takes the larger size.
  preset.material.setMap(MapSlot::Roughness, std::make_shared<Image>(8, 8, 1));
  const std::string larger = freshFolder("gltf-metallic-larger");
  gltfPath = exportGltf(preset, makePlane(2.0f, 1), larger);
  ASSERT_TRUE(gltfPath.ok()) << gltfPath.error();
  const QJsonObject both = readJson(gltfPath.value());
  Result<Image> packedBoth = loadImage(
      larger + "/" + both["images"].toArray()[source].toObject()["uri"].toString().toStdString());
  ASSERT_TRUE(packedBoth.ok()) << packedBoth.error();
  EXPECT_EQ(packedBoth->width(), 8);
}

TEST(GodotExport, DepthMapsFlipAndSimpleParallaxIsNotDeep) {
  Preset preset = syntheticPreset();
  preset.material.setTechnique(Technique::ParallaxLimited);
  preset.material.setParameter(ParamId::HeightIsDepth, 1.0);
  preset.material.setParameter(ParamId::HeightBias, 0.0);
  Result<EngineExportResult> exported = exportGodot(preset, freshFolder("godot-flat"));
  ASSERT_TRUE(exported.ok()) << exported.error();
  const GodotResource tres = parseTres(exported->mainPath);
  EXPECT_EQ(tres.properties.at("heightmap_deep_parallax"), "false");
  EXPECT_EQ(tres.properties.count("heightmap_min_layers"), 0u);
  EXPECT_EQ(tres.properties.at("heightmap_flip_texture"), "true");
  // A bias that does not put the top on the surface cannot be expressed: the user is told.
  bool biasNoted = false;
  for (const std::string& note : exported->notes)
    biasNoted = biasNoted || note.find("heightBias") != std::string::npos;
  EXPECT_TRUE(biasNoted);
}

TEST(GodotExport, NormalMappingOnlyLeavesHeightOff) {
  Preset preset = syntheticPreset();
  preset.material.setTechnique(Technique::Normal);
  Result<EngineExportResult> exported = exportGodot(preset, freshFolder("godot-normal"));
  ASSERT_TRUE(exported.ok()) << exported.error();
  const GodotResource tres = parseTres(exported->mainPath);
  EXPECT_EQ(tres.properties.count("heightmap_enabled"), 0u);
  EXPECT_EQ(tres.properties.at("normal_enabled"), "true");
}

// The Godot preview mode traces what the .tres holds: heightmap_scale * 0.01 as the depth, the
// deep parallax switch as the trace, the layer counts.
TEST(GodotExport, EnginePreviewTracesTheTresHeightmapSettings) {
  for (Technique technique : {Technique::Pom, Technique::ParallaxLimited}) {
    Preset preset = syntheticPreset();
    preset.material.setTechnique(technique);
    const std::string folder = freshFolder("godot-preview");
    Result<EngineExportResult> exported = exportGodot(preset, folder);
    ASSERT_TRUE(exported.ok()) << exported.error();
    const auto& p = parseTres(exported->mainPath).properties;
    const EngineTraceParams trace = engineTrace(preset.material, Engine::Godot);
    EXPECT_DOUBLE_EQ(trace.depth, std::stod(p.at("heightmap_scale")) * 0.01);
    const bool deep = p.at("heightmap_deep_parallax") == "true";
    EXPECT_EQ(deep, technique == Technique::Pom);
    EXPECT_EQ(trace.trace, deep ? EngineTrace::GodotDeep : EngineTrace::GodotOffset);
    if (deep) {
      EXPECT_DOUBLE_EQ(trace.minSteps, std::stod(p.at("heightmap_min_layers")));
      EXPECT_DOUBLE_EQ(trace.maxSteps, std::stod(p.at("heightmap_max_layers")));
    }
  }
}

}  // namespace
}  // namespace relief::core
