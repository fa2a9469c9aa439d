// Exporter; see Exporter.h.
#include "core/exporters/Exporter.h"

#include "core/exporters/GltfExport.h"
#include "core/exporters/GodotExport.h"
#include "core/exporters/UnityExport.h"
#include "core/exporters/UnrealExport.h"

#include <array>

namespace relief::core::inline exporters {
namespace {

Result<ExportResult> fromPath(Result<std::string> written) {
  if (!written)
    return makeError(written.error());
  return ExportResult{std::move(written).value(), {}};
}

Result<ExportResult> fromEngine(Result<EngineExportResult> written) {
  if (!written)
    return makeError(written.error());
  return ExportResult{written->mainPath, written->notes};
}

Result<ExportResult> runPackage(const ExportRequest& request, const WorkControl& control) {
  return fromPath(exportPackage(request.preset, request.folder, request.package, control));
}
Result<ExportResult> runGltf(const ExportRequest& request, const WorkControl&) {
  return fromPath(exportGltf(request.preset, request.mesh, request.folder));
}
Result<ExportResult> runGodot(const ExportRequest& request, const WorkControl&) {
  return fromEngine(exportGodot(request.preset, request.folder));
}
Result<ExportResult> runUnreal(const ExportRequest& request, const WorkControl&) {
  return fromEngine(exportUnreal(request.preset, request.folder));
}
Result<ExportResult> runUnityUrp(const ExportRequest& request, const WorkControl&) {
  return fromEngine(exportUnity(request.preset, request.folder, UnityPipeline::Urp));
}
Result<ExportResult> runUnityHdrp(const ExportRequest& request, const WorkControl&) {
  return fromEngine(exportUnity(request.preset, request.folder, UnityPipeline::Hdrp));
}

constexpr std::array kKinds = {
    ExportKindInfo{ExportKind::Package, "package", "Package: maps and a preset in a folder",
                   "The maps in the chosen format and a .relief preset pointing at them: a "
                   "folder to copy into another project or hand to a colleague.",
                   false, true, runPackage},
    ExportKindInfo{ExportKind::Gltf, "gltf", "glTF 2.0: mesh and material (.gltf, .bin, textures)",
                   "The mesh with a metallic-roughness material (base colour, normal, "
                   "occlusion). glTF has no parallax: the height map and every Relief parameter "
                   "go into the material's extras.relief. See docs/export.md.",
                   true, false, runGltf},
    ExportKindInfo{ExportKind::Godot, "godot", "Godot 4: StandardMaterial3D (.tres and textures)",
                   "Godot's heightmap settings converted from Relief's (scale, deep parallax, "
                   "layers, flips); what Godot cannot show is listed after the export. See "
                   "docs/export.md.",
                   false, false, runGodot},
    ExportKindInfo{ExportKind::Unreal, "unreal",
                   "Unreal Engine: textures, manifest and import script",
                   "BaseColor, Normal (DirectX, green down), ORM (occlusion, roughness, metallic) "
                   "and Height textures, a JSON manifest with the ParallaxOcclusionMapping "
                   "function's inputs converted from Relief's, and a Python script that builds "
                   "the material in the Unreal Editor. See docs/export.md.",
                   false, false, runUnreal},
    ExportKindInfo{ExportKind::UnityUrp, "unity", "Unity URP Lit: .mat, textures and .meta files",
                   "A Universal Render Pipeline Lit material with its textures (metallic/"
                   "smoothness, occlusion, normal and height maps) and .meta files: copy the "
                   "folder into Assets/. URP's parallax is single-step. See docs/export.md.",
                   false, false, runUnityUrp},
    ExportKindInfo{ExportKind::UnityHdrp, "unity-hdrp",
                   "Unity HDRP Lit: .mat, textures and .meta files",
                   "A High Definition Render Pipeline Lit material with its textures (mask map, "
                   "normal and height maps) and .meta files, the relief as HDRP's pixel "
                   "displacement (POM): copy the folder into Assets/. See docs/export.md.",
                   false, false, runUnityHdrp},
};

static_assert(kKinds.size() == kExportKindCount, "one row per export kind");
constexpr bool rowsInEnumOrder() {
  for (std::size_t i = 0; i < kKinds.size(); ++i) {
    if (std::size_t(kKinds[i].kind) != i)
      return false;
  }
  return true;
}
static_assert(rowsInEnumOrder(), "exportKindInfo indexes the rows by kind");

constexpr std::array kMapFormats = {
    ExportChoice<PackageMapFormat>{PackageMapFormat::Png16, "png16", "16-bit PNG"},
    ExportChoice<PackageMapFormat>{PackageMapFormat::Png8, "png", "8-bit PNG (dithered)"},
    ExportChoice<PackageMapFormat>{PackageMapFormat::Exr, "exr", "32-bit float EXR"},
};

constexpr std::array kTextureChoices = {
    ExportChoice<PackageTextures>{PackageTextures::Ktx2, "ktx2", "KTX2"},
    ExportChoice<PackageTextures>{PackageTextures::DdsWherePossible, "dds",
                                  "DDS for BC formats, KTX2 for the rest"},
    ExportChoice<PackageTextures>{PackageTextures::None, "none", "None"},
};

static_assert(kMapFormats[0].value == PackageOptions{}.dataMaps, "the first is the default");
static_assert(kTextureChoices[0].value == PackageOptions{}.textures, "the first is the default");

}  // namespace

std::span<const ExportKindInfo> allExportKinds() {
  return kKinds;
}

const ExportKindInfo& exportKindInfo(ExportKind kind) {
  return kKinds[std::size_t(kind)];
}

std::optional<ExportKind> findExportKind(std::string_view name) {
  for (const ExportKindInfo& info : kKinds) {
    if (info.name == name)
      return info.kind;
  }
  return std::nullopt;
}

std::span<const ExportChoice<PackageMapFormat>> packageMapFormats() {
  return kMapFormats;
}

std::span<const ExportChoice<PackageTextures>> packageTextureChoices() {
  return kTextureChoices;
}

Result<ExportResult> exportMaterial(const ExportRequest& request, const WorkControl& control) {
  if (control.cancelled())
    return makeError("cancelled");
  return exportKindInfo(request.kind).run(request, control);
}

}  // namespace relief::core::exporters
