// UnityExport; see UnityExport.h and docs/export.md for the conversions.
#include "core/exporters/UnityExport.h"

#include "core/base/AtomicFile.h"
#include "core/exporters/PackageExport.h"
#include "core/image/ImageIO.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>

namespace relief::core::inline exporters {
namespace {

// The shaders' GUIDs are fixed in every Unity project that has the pipeline package.
constexpr const char* kUrpLitShaderGuid = "933532a4fcc9baf4fa0491de14d08ed7";
constexpr const char* kHdrpLitShaderGuid = "6e4ae4064600d784cac1e41a9e6f2e59";

// HDRP Lit's sample counts for pixel displacement are sliders of 1..64.

struct UnityTexture {
  std::string property;  // the shader property, e.g. _BaseMap
  std::string file;
  std::string guid;
};

// Unity's importer settings for one texture. Its default size limit is 2048, so the limit is
// raised to the image's size; data maps are linear; a 16-bit height map stays uncompressed, as
// block compression would keep 8 bits and terrace the relief.
std::string textureMeta(const std::string& guid, const Image& image, bool srgb, bool normalMap,
                        bool uncompressed) {
  int maxSize = 32;
  while (maxSize < std::max(image.width(), image.height()) && maxSize < 16384)
    maxSize *= 2;
  std::ostringstream meta;
  meta << "fileFormatVersion: 2\n"
       << "guid: " << guid << "\n"
       << "TextureImporter:\n"
       << "  internalIDToNameTable: []\n"
       << "  externalObjects: {}\n"
       << "  serializedVersion: 12\n"
       << "  mipmaps:\n"
       << "    mipMapMode: 0\n"
       << "    enableMipMap: 1\n"
       << "    sRGBTexture: " << (srgb ? 1 : 0) << "\n"
       << "    linearTexture: 0\n"
       << "  bumpmap:\n"
       << "    convertToNormalMap: 0\n"
       << "  isReadable: 0\n"
       << "  maxTextureSize: " << maxSize << "\n"
       << "  textureSettings:\n"
       << "    serializedVersion: 2\n"
       << "    filterMode: 1\n"
       << "    aniso: 4\n"
       << "    mipBias: 0\n"
       << "    wrapU: 0\n"
       << "    wrapV: 0\n"
       << "    wrapW: 0\n"
       << "  textureType: " << (normalMap ? 1 : 0) << "\n"
       << "  textureShape: 1\n"
       << "  alphaUsage: 1\n"
       << "  alphaIsTransparency: 0\n"
       << "  platformSettings:\n"
       << "  - serializedVersion: 3\n"
       << "    buildTarget: DefaultTexturePlatform\n"
       << "    maxTextureSize: " << maxSize << "\n"
       << "    textureFormat: -1\n"
       << "    textureCompression: " << (uncompressed ? 0 : 1) << "\n"
       << "    compressionQuality: 50\n"
       << "    overridden: 0\n"
       << "  userData: \n"
       << "  assetBundleName: \n"
       << "  assetBundleVariant: \n";
  return meta.str();
}

std::string materialMeta(const std::string& guid) {
  return "fileFormatVersion: 2\nguid: " + guid +
         "\nNativeFormatImporter:\n  externalObjects: {}\n  mainObjectFileID: 2100000\n"
         "  userData: \n  assetBundleName: \n  assetBundleVariant: \n";
}

// The .mat: Unity's YAML serialisation of a Material (serializedVersion 8, Unity 2021.2 and
// later, with the keyword lists the pipelines' editors would set).
struct UnityMaterial {
  std::string name;
  std::string shaderGuid;
  std::vector<std::string> keywords;
  std::vector<UnityTexture> textures;
  double tiling = 1.0;
  std::vector<std::pair<std::string, double>> floats;
  std::vector<std::pair<std::string, std::string>> colors;  // name, "{r: .., g: .., ...}"
  int renderQueue = -1;
};

std::string materialYaml(const UnityMaterial& material) {
  std::ostringstream mat;
  mat << "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!21 &2100000\nMaterial:\n"
      << "  serializedVersion: 8\n"
      << "  m_ObjectHideFlags: 0\n"
      << "  m_CorrespondingSourceObject: {fileID: 0}\n"
      << "  m_PrefabInstance: {fileID: 0}\n"
      << "  m_PrefabAsset: {fileID: 0}\n"
      << "  m_Name: " << material.name << "\n"
      << "  m_Shader: {fileID: 4800000, guid: " << material.shaderGuid << ", type: 3}\n"
      << "  m_Parent: {fileID: 0}\n"
      << "  m_ModifiedSerializedProperties: 0\n"
      << "  m_ValidKeywords:" << (material.keywords.empty() ? " []" : "") << "\n";
  for (const std::string& keyword : material.keywords)
    mat << "  - " << keyword << "\n";
  mat << "  m_InvalidKeywords: []\n"
      << "  m_LightmapFlags: 4\n"
      << "  m_EnableInstancingVariants: 0\n"
      << "  m_DoubleSidedGI: 0\n"
      << "  m_CustomRenderQueue: " << material.renderQueue << "\n"
      << "  stringTagMap:\n    RenderType: Opaque\n"
      << "  disabledShaderPasses: []\n"
      << "  m_LockedProperties: \n"
      << "  m_SavedProperties:\n"
      << "    serializedVersion: 3\n"
      << "    m_TexEnvs:\n";
  const std::string tiling = engineNumber(material.tiling);
  for (const UnityTexture& texture : material.textures) {
    mat << "    - " << texture.property << ":\n"
        << "        m_Texture: {fileID: 2800000, guid: " << texture.guid << ", type: 3}\n"
        << "        m_Scale: {x: " << tiling << ", y: " << tiling << "}\n"
        << "        m_Offset: {x: 0, y: 0}\n";
  }
  mat << "    m_Ints: []\n    m_Floats:\n";
  for (const auto& [name, value] : material.floats)
    mat << "    - " << name << ": " << engineNumber(value) << "\n";
  mat << "    m_Colors:\n";
  for (const auto& [name, value] : material.colors)
    mat << "    - " << name << ": " << value << "\n";
  mat << "  m_BuildTextureStacks: []\n";
  return mat.str();
}

class UnityWriter {
 public:
  UnityWriter(const std::filesystem::path& folder, std::string stem)
      : m_folder(folder), m_stem(std::move(stem)) {}

  // Writes <stem>_<suffix>.png and its .meta; returns the texture for the material.
  Result<UnityTexture> texture(const std::string& property, const std::string& suffix,
                               const Image& image, SampleFormat format, bool srgb, bool normalMap) {
    const std::string file = m_stem + "_" + suffix + ".png";
    if (Status saved = saveImage(image, (m_folder / file).string(), format); !saved)
      return makeError(saved.error());
    UnityTexture texture{property, file, guidFor(file)};
    const bool uncompressed = format == SampleFormat::UInt16;
    if (Status written =
            writeFileAtomically((m_folder / (file + ".meta")).string(),
                                textureMeta(texture.guid, image, srgb, normalMap, uncompressed));
        !written) {
      return makeError(written.error());
    }
    return texture;
  }

  std::string guidFor(const std::string& file) const {
    // The folder is part of the name, so two exports of like-named materials into one project
    // do not collide, while exporting again into the same folder keeps the GUIDs.
    return stableGuid(std::filesystem::absolute(m_folder).lexically_normal().string() + "/" + file);
  }

 private:
  std::filesystem::path m_folder;
  std::string m_stem;
};

// The material's maps as Unity textures with .meta files, and the keywords they switch on;
// `masks` is the packed metallic/smoothness (URP) or mask map (HDRP), if the material has one.
Status writeUnityTextures(UnityWriter& writer, const Material& material, bool urp,
                          UnityMaterial& mat, std::optional<Image>& masks) {
  const auto add = [&](Result<UnityTexture> texture) -> Status {
    if (!texture)
      return makeError(texture.error());
    mat.textures.push_back(texture.value());
    return {};
  };
  if (const Image* color = material.image(MapSlot::Color)) {
    // Both pipelines keep _MainTex for scripts written for the built-in pipeline.
    Result<UnityTexture> base = writer.texture(urp ? "_BaseMap" : "_BaseColorMap", "BaseMap",
                                               *color, SampleFormat::UInt8, true, false);
    if (!base)
      return makeError(base.error());
    mat.textures.push_back(base.value());
    mat.textures.push_back({"_MainTex", base->file, base->guid});
  }
  const bool yDown = material.parameterFlag(ParamId::NormalYDown);
  if (const Image* normals = material.image(MapSlot::Normal)) {
    // Unity's normal maps are +Y up (OpenGL).
    if (Status s =
            add(writer.texture(urp ? "_BumpMap" : "_NormalMap", "Normal",
                               openGlNormalMap(*normals, yDown), SampleFormat::UInt8, false, true));
        !s)
      return makeError(s.error());
    mat.keywords.push_back("_NORMALMAP");
    if (!urp)
      mat.keywords.push_back("_NORMALMAP_TANGENT_SPACE");
  }
  masks = packEngineMasks(material, urp ? "unity-metallic" : "unity-mask");
  if (masks) {
    if (Status s = add(writer.texture(urp ? "_MetallicGlossMap" : "_MaskMap",
                                      urp ? "MetallicSmoothness" : "MaskMap", *masks,
                                      SampleFormat::UInt8, false, false));
        !s)
      return makeError(s.error());
    mat.keywords.push_back(urp ? "_METALLICSPECGLOSSMAP" : "_MASKMAP");
  }
  const Image* occlusion = material.image(MapSlot::AmbientOcclusion);
  if (urp && occlusion) {
    // URP reads occlusion from its own map's green channel; a grey map has it everywhere.
    if (Status s = add(writer.texture("_OcclusionMap", "Occlusion", *occlusion, SampleFormat::UInt8,
                                      false, false));
        !s)
      return makeError(s.error());
    mat.keywords.push_back("_OCCLUSIONMAP");
  }
  if (exportsParallax(material)) {
    const Image height = engineHeightMap(*material.image(MapSlot::Height),
                                         material.parameterFlag(ParamId::HeightIsDepth));
    if (Status s = add(writer.texture(urp ? "_ParallaxMap" : "_HeightMap", "Height", height,
                                      SampleFormat::UInt16, false, false));
        !s)
      return makeError(s.error());
  }
  return {};
}

// URP Lit's properties, its one-step parallax and what it cannot express.
void setUrpProperties(const Material& material, bool parallax, UnityMaterial& mat,
                      std::vector<std::string>& notes) {
  const double scale = material.parameter(ParamId::HeightScale);
  const double bias = material.parameter(ParamId::HeightBias);
  mat.floats.push_back({"_WorkflowMode", 1.0});  // metallic
  mat.floats.push_back({"_SmoothnessTextureChannel", 0.0});
  mat.floats.push_back({"_BumpScale", material.parameter(ParamId::NormalStrength)});
  mat.floats.push_back({"_OcclusionStrength", 1.0});
  mat.floats.push_back({"_Surface", 0.0});
  mat.floats.push_back({"_Cull", 2.0});
  if (parallax) {
    const double amplitude = urpParallaxAmplitude(scale);
    mat.keywords.push_back("_PARALLAXMAP");
    mat.floats.push_back({"_Parallax", amplitude});
    if (amplitude < 0.005 || amplitude > 0.08) {
      notes.push_back("URP's Height Map slider spans 0.005-0.08; _Parallax " +
                      engineNumber(amplitude) +
                      " is stored as is and renders so, but touching the slider clamps it");
    }
    if (std::abs(bias + scale / 2) > 1e-6) {
      notes.push_back("URP puts the middle of the relief on the surface; Relief's heightBias " +
                      engineNumber(bias) + " puts it " + engineNumber(std::abs(bias + scale / 2)) +
                      " texture widths " + (bias + scale / 2 < 0 ? "lower" : "higher") +
                      ", which URP cannot express");
    }
    if (isOccludingRelief(material.technique())) {
      notes.push_back(
          "URP Lit has only single-step parallax (offset limiting with view.z + 0.42); "
          "Relief's occluding relief needs HDRP's pixel displacement or a Shader Graph POM");
    }
  }
}

// HDRP Lit's properties, its pixel displacement (POM) and what it cannot express.
void setHdrpProperties(const Material& material, bool parallax, UnityMaterial& mat,
                       std::vector<std::string>& notes) {
  const double scale = material.parameter(ParamId::HeightScale);
  const double bias = material.parameter(ParamId::HeightBias);
  mat.renderQueue = 2225;                      // HDRP Lit's opaque queue
  mat.floats.push_back({"_MaterialID", 1.0});  // standard
  mat.floats.push_back({"_NormalScale", material.parameter(ParamId::NormalStrength)});
  mat.floats.push_back({"_NormalMapSpace", 0.0});
  for (const char* remap : {"_MetallicRemap", "_SmoothnessRemap", "_AORemap"}) {
    mat.floats.push_back({std::string(remap) + "Min", 0.0});
    mat.floats.push_back({std::string(remap) + "Max", 1.0});
  }
  if (parallax) {
    const HdrpPixelDisplacement ppd = hdrpPixelDisplacement(material);
    const bool deep = isOccludingRelief(material.technique());
    mat.keywords.push_back("_HEIGHTMAP");
    mat.keywords.push_back("_PIXEL_DISPLACEMENT");
    mat.floats.push_back({"_DisplacementMode", 2.0});  // pixel displacement: HDRP's POM
    mat.floats.push_back({"_HeightPoMAmplitude", ppd.amplitudeCm});
    // What HDRP's material editor derives from the amplitude, set here so the material is
    // right before anyone opens it: metres, and the top of the relief on the surface.
    mat.floats.push_back({"_HeightAmplitude", ppd.amplitudeCm * 0.01});
    mat.floats.push_back({"_HeightCenter", 1.0});
    mat.floats.push_back({"_PPDPrimitiveLength", ppd.primitiveMetres});
    mat.floats.push_back({"_PPDPrimitiveWidth", ppd.primitiveMetres});
    mat.colors.push_back({"_InvPrimScale", "{r: 1, g: 1, b: 0, a: 0}"});
    mat.floats.push_back({"_DisplacementLockTilingScale", ppd.lockTilingScale ? 1.0 : 0.0});
    mat.floats.push_back({"_PPDMinSamples", ppd.minSamples});
    mat.floats.push_back({"_PPDMaxSamples", ppd.maxSamples});
    mat.floats.push_back({"_PPDLodThreshold", ppd.lodThreshold});
    mat.floats.push_back({"_DepthOffsetEnable", ppd.depthOffset ? 1.0 : 0.0});
    if (ppd.depthOffset)
      mat.keywords.push_back("_DEPTHOFFSET_ON");
    notes.push_back(
        "HDRP measures the relief in centimetres on a primitive of _PPDPrimitiveLength x "
        "_PPDPrimitiveWidth metres (set to 1 x 1 here, a 1 m quad): set them to the size "
        "your mesh's texture spans to keep the depth");
    if (std::abs(bias + scale) > 1e-6) {
      notes.push_back("HDRP puts the top of the relief on the surface; heightBias " +
                      engineNumber(bias) + " (not -heightScale) has no HDRP equivalent");
    }
    if (!deep) {
      notes.push_back(
          "HDRP has no single-step parallax: exported as pixel displacement with one sample");
    }
    if (material.parameter(ParamId::MaxSamples) > kHdrpMaxSamples && deep) {
      notes.push_back("HDRP takes at most 64 samples; maxSamples " +
                      engineNumber(material.parameter(ParamId::MaxSamples)) + " was lowered to 64");
    }
  }
}

}  // namespace

Result<EngineExportResult> exportUnity(const Preset& preset, const std::string& folder,
                                       UnityPipeline pipeline) {
  if (Status made = makeExportFolder(folder); !made)
    return makeError(made.error());
  const Material& material = preset.material;
  const std::string stem = exportStem(material);
  const bool urp = pipeline == UnityPipeline::Urp;
  UnityWriter writer(folder, stem);
  EngineExportResult result;

  UnityMaterial mat;
  mat.name = stem;
  mat.shaderGuid = urp ? kUrpLitShaderGuid : kHdrpLitShaderGuid;
  mat.tiling = material.parameter(ParamId::Tiling);
  std::optional<Image> masks;
  if (Status written = writeUnityTextures(writer, material, urp, mat, masks); !written)
    return makeError(written.error());
  for (std::string& loss : engineLosses(material, urp ? Engine::Unity : Engine::UnityHdrp))
    result.notes.push_back(std::move(loss));

  // Relief's smoothness when no map carries it: Unity's smoothness is 1 - perceptual roughness.
  // With a map, URP multiplies the map's alpha by _Smoothness and HDRP remaps the mask's alpha
  // from _SmoothnessRemapMin..Max, so those stay neutral.
  mat.floats.push_back({"_Metallic", exportedMetallic(material)});
  mat.floats.push_back({"_Smoothness", masks ? 1.0 : 1.0 - exportedRoughness(material)});
  mat.colors.push_back({"_BaseColor", "{r: 1, g: 1, b: 1, a: 1}"});
  mat.colors.push_back({"_Color", "{r: 1, g: 1, b: 1, a: 1}"});
  const bool parallax = exportsParallax(material);
  if (urp)
    setUrpProperties(material, parallax, mat, result.notes);
  else
    setHdrpProperties(material, parallax, mat, result.notes);

  const std::filesystem::path directory(folder);
  const std::string matFile = stem + ".mat";
  result.mainPath = (directory / matFile).string();
  if (Status written = writeFileAtomically(result.mainPath, materialYaml(mat)); !written)
    return makeError(written.error());
  if (Status written = writeFileAtomically((directory / (matFile + ".meta")).string(),
                                           materialMeta(writer.guidFor(matFile)));
      !written) {
    return makeError(written.error());
  }
  return result;
}

}  // namespace relief::core::inline exporters
