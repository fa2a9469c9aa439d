// The map generators as the GUI, presets and CLI see them: a table of generators, each with its
// inputs, default destination slot and options (OptionSpec: name, unit, range, default —
// declared once), and one entry point that runs any of them. The algorithms are pure functions
// in the files next to this one.
#pragma once

#include "core/base/OptionSpec.h"
#include "core/base/Result.h"
#include "core/base/WorkControl.h"
#include "core/generators/ChannelPacking.h"
#include "core/image/Image.h"
#include "core/material/MapSlot.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace relief::core::inline generators {

enum class GeneratorKind {
  Normal,            // normal from height
  Height,            // height from normal (Frankot-Chellappa)
  HeightFromColor,   // height from a colour photograph
  AmbientOcclusion,  // AO from height
  Curvature,         // curvature from height or normal
  Pack,              // channel packing: height into the normal map's alpha, ORM, mask maps
  Delight,           // a photograph's baked light divided out (albedo)
  Roughness,         // a roughness guess from colour (and height)
  Metallic,          // a metallic guess from colour
};

struct GeneratorInput {
  std::string_view name;   // the CLI option (--in, --normal, --height)
  std::string_view label;  // what the GUI asks for
  MapSlot defaultSlot;     // where the GUI takes it from by default
  bool optional = false;   // may be missing (null in GeneratorRequest::inputs)
};

struct GeneratorInfo {
  GeneratorKind kind;
  std::string_view name;  // relief-cli generate <name>
  std::string_view label;
  std::string_view description;
  std::vector<GeneratorInput> inputs;
  MapSlot output;  // the slot the result goes to by default
  std::vector<OptionSpec> options;
};

std::span<const GeneratorInfo> allGenerators();
const GeneratorInfo& generatorInfo(GeneratorKind kind);
std::optional<GeneratorKind> findGenerator(std::string_view name);

// Option values in the order of GeneratorInfo::options.
using GeneratorValues = std::vector<double>;
GeneratorValues defaultGeneratorValues(GeneratorKind kind);
// Index of an option by name, or -1.
int findGeneratorOption(GeneratorKind kind, std::string_view name);

struct GeneratorRequest {
  GeneratorKind kind = GeneratorKind::Normal;
  std::vector<const Image*> inputs;  // in the order of GeneratorInfo::inputs; null: not given
  GeneratorValues values;            // defaults when empty
  // The inputs' size relative to the full-size map (previews run at a fraction); options in
  // texels and per-texel strengths are scaled so the preview looks like the result.
  double texelScale = 1.0;
};

struct GeneratedMap {
  Image image;
  std::vector<std::string> notes;     // what the artist should know (ranges, suggestions)
  std::optional<LevelsRange> levels;  // pack with auto-levels: the height range stretched
  std::optional<double> depthTexels;  // height from normal: the relief's depth in texels
};

// Runs one generator. Fails with a message for missing or mismatched inputs, or when cancelled.
// Optional inputs may be null, and trailing ones left out of the list.
Result<GeneratedMap> runGenerator(const GeneratorRequest& request, const WorkControl& control = {});

// A warning when an image used as a normal map does not look like one (e.g. a photograph):
// many texels whose decoded vector is far from unit length or points into the surface.
std::optional<std::string> normalMapWarning(const Image& image);

}  // namespace relief::core::inline generators
