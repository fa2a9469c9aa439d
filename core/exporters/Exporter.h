// What Relief exports, declared once: the kinds (package, glTF 2.0, Godot 4, Unreal, Unity URP
// and HDRP) with their names
// (the CLI's --to), labels and descriptions (the export dialog), the package's map-file and
// compressed-texture choices (--maps, --textures and the dialog's boxes), and one entry point
// that runs any kind, so the CLI and the dialog only parse, show and report.
#pragma once

#include "core/base/Result.h"
#include "core/base/WorkControl.h"
#include "core/exporters/PackageExport.h"
#include "core/mesh/Mesh.h"
#include "core/preset/MaterialPreset.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace relief::core::inline exporters {

enum class ExportKind { Package, Gltf, Godot, Unreal, UnityUrp, UnityHdrp };
// How many kinds there are (the last one + 1): Exporter.cpp's table has a row for each.
inline constexpr std::size_t kExportKindCount = std::size_t(ExportKind::UnityHdrp) + 1;

struct ExportRequest;
struct ExportResult;

struct ExportKindInfo {
  ExportKind kind;
  std::string_view name;         // relief-cli export --to <name>
  std::string_view label;        // the dialog's choice
  std::string_view description;  // --help and the dialog's explanation
  bool usesMesh;                 // glTF carries the mesh
  bool usesPackageOptions;       // map file format and compressed textures
  // Writes the files (the kind's implementation file); exportMaterial dispatches through it.
  Result<ExportResult> (*run)(const ExportRequest& request, const WorkControl& control);
};

std::span<const ExportKindInfo> allExportKinds();
const ExportKindInfo& exportKindInfo(ExportKind kind);
std::optional<ExportKind> findExportKind(std::string_view name);

// A named value of one of the package's choices.
template <class Value>
struct ExportChoice {
  Value value;
  std::string_view name;   // the CLI's spelling
  std::string_view label;  // the dialog's
};

// In the order the dialog lists them; the first is the default (PackageOptions{}).
std::span<const ExportChoice<PackageMapFormat>> packageMapFormats();
std::span<const ExportChoice<PackageTextures>> packageTextureChoices();

template <class Value>
std::optional<Value> findExportChoice(std::span<const ExportChoice<Value>> choices,
                                      std::string_view name) {
  for (const ExportChoice<Value>& choice : choices) {
    if (choice.name == name)
      return choice.value;
  }
  return std::nullopt;
}

struct ExportRequest {
  ExportKind kind = ExportKind::Package;
  Preset preset;
  Mesh mesh;  // glTF only
  std::string folder;
  PackageOptions package;  // package only
};

struct ExportResult {
  std::string writtenPath;  // the main file: the preset, .gltf, .tres, .mat or Unreal manifest
  std::vector<std::string> notes;  // what the engine cannot show exactly
};

// Runs the export. Fails with a message naming the file, or with "cancelled" (checked between
// maps and inside compression); a cancelled export may leave part of its files in the folder.
Result<ExportResult> exportMaterial(const ExportRequest& request, const WorkControl& control = {});

}  // namespace relief::core::exporters
