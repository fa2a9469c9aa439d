// make-samples: writes the bundled sample materials (samples/<name>/) deterministically: a
// colour map (sRGB PNG), a normal map baked from the height for the material's relief depth,
// a 16-bit height map and a .relief preset. Run: make-samples <samples-folder> [size].
#include "SampleMaterials.h"

#include "core/generators/NormalFromHeight.h"
#include "core/image/ColorSpace.h"
#include "core/image/ImageIO.h"
#include "core/preset/MaterialPreset.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

namespace {

using namespace relief;

core::Image encodeSrgb(const core::Image& linear) {
  core::Image encoded = linear;
  for (std::size_t i = 0; i < encoded.valueCount(); ++i) {
    encoded.data()[i] = core::linearToSrgb(encoded.data()[i]);
  }
  encoded.setColorSpace(core::ColorSpace::Srgb);
  return encoded;
}

bool writeSample(const tools::SampleMaterial& sample, const std::filesystem::path& root) {
  const std::filesystem::path folder = root / sample.name;
  std::filesystem::create_directories(folder);
  const std::string base = (folder / sample.name).string();

  // Central differences, as the samples were first made (a kernel change would change them).
  core::NormalFromHeightOptions normalOptions;
  normalOptions.kernel = core::GradientKernel::Central;
  normalOptions.strength = float(sample.heightScale * sample.height.width());
  normalOptions.edge = core::EdgeMode::Wrap;
  const core::Image normal = core::normalMapFromHeight(sample.height, normalOptions);

  const struct {
    const core::Image* image;
    std::string path;
    core::SampleFormat format;
    core::MapSlot slot;
  } maps[] = {
      {nullptr, base + "_color.png", core::SampleFormat::UInt8, core::MapSlot::Color},
      {&normal, base + "_normal.png", core::SampleFormat::UInt8, core::MapSlot::Normal},
      {&sample.height, base + "_height.png", core::SampleFormat::UInt16, core::MapSlot::Height},
  };
  const core::Image color = encodeSrgb(sample.colorLinear);

  core::Material material;
  material.setName(sample.name);
  // Parallax occlusion mapping with soft self-shadows; the relief's top on the mesh surface
  // (heightBias = -heightScale), the depth the normal map was baked for.
  material.setTechnique(core::Technique::Pom);
  material.setParameter(core::ParamId::HeightScale, sample.heightScale);
  material.setParameter(core::ParamId::HeightBias, -sample.heightScale);
  material.setParameter(core::ParamId::ShadowMode, double(core::ShadowMode::Soft));
  material.setParameter(core::ParamId::Tiling, sample.tiling);
  material.setParameter(core::ParamId::Specular, sample.specular);
  material.setParameter(core::ParamId::Shininess, sample.shininess);
  for (const auto& map : maps) {
    const core::Image& image = map.image ? *map.image : color;
    if (core::Status saved = core::saveImage(image, map.path, map.format); !saved) {
      std::fprintf(stderr, "make-samples: %s\n", saved.error().c_str());
      return false;
    }
    material.setMap(map.slot, std::make_shared<core::Image>(image), map.path);
  }
  core::Preset preset;
  preset.material = material;
  if (auto saved = core::savePreset(preset, base + ".relief"); !saved) {
    std::fprintf(stderr, "make-samples: %s\n", saved.error().c_str());
    return false;
  }
  std::printf("wrote %s (%dx%d, heightScale %.3f)\n", base.c_str(), sample.height.width(),
              sample.height.height(), sample.heightScale);
  return true;
}

}  // namespace

int main(int argc, char* argv[]) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: make-samples <samples-folder> [size, default 1024]\n");
    return 2;
  }
  const int size = argc == 3 ? std::atoi(argv[2]) : 1024;
  if (size < 16 || size > 8192) {
    std::fprintf(stderr, "make-samples: size must be 16..8192\n");
    return 2;
  }
  for (const tools::SampleMaterial& sample : tools::makeAllSamples(size)) {
    // Absolute, so the preset can store map paths relative to itself.
    if (!writeSample(sample, std::filesystem::absolute(argv[1])))
      return 1;
  }
  return 0;
}
