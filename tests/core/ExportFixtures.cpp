// ExportFixtures; see ExportFixtures.h.
#include "ExportFixtures.h"

#include "support/TestPaths.h"

#include <filesystem>
#include <memory>

namespace relief::core {

std::string freshFolder(const std::string& name) {
  const std::string folder = test::scratchFolder() + "/" + name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

Preset syntheticPreset() {
  constexpr int kSize = 16;
  auto color = std::make_shared<Image>(kSize, kSize, 3, ColorSpace::Srgb);
  auto normal = std::make_shared<Image>(kSize, kSize, 3);
  auto height = std::make_shared<Image>(kSize, kSize, 1);
  auto occlusion = std::make_shared<Image>(kSize, kSize, 1);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      color->at(x, y, 0) = float(x) / (kSize - 1);
      color->at(x, y, 1) = float(y) / (kSize - 1);
      color->at(x, y, 2) = 0.5f;
      normal->at(x, y, 0) = 0.75f;
      normal->at(x, y, 1) = 0.25f;  // y down: the surface tilts so that +y is 0.75 in OpenGL
      normal->at(x, y, 2) = 0.9f;
      height->at(x, y, 0) = float(x + y * kSize) / (kSize * kSize - 1);
      occlusion->at(x, y, 0) = 0.5f + 0.5f * float(y) / (kSize - 1);
    }
  }
  Preset preset;
  preset.material.setName("test brick");  // the space must not reach file names
  preset.material.setMap(MapSlot::Color, color);
  preset.material.setMap(MapSlot::Normal, normal);
  preset.material.setMap(MapSlot::Height, height);
  preset.material.setMap(MapSlot::AmbientOcclusion, occlusion);
  preset.material.setTechnique(Technique::Pom);
  preset.material.setParameter(ParamId::HeightScale, 0.06);
  preset.material.setParameter(ParamId::HeightBias, -0.06);
  preset.material.setParameter(ParamId::MinSamples, 12);
  preset.material.setParameter(ParamId::MaxSamples, 48);
  preset.material.setParameter(ParamId::Tiling, 2.0);
  preset.material.setParameter(ParamId::NormalYDown, 1.0);
  // Classic shading: the exports convert its shininess (roughness (2/4)^(1/4)).
  preset.material.setParameter(ParamId::Shading, double(int(ShadingModel::Classic)));
  preset.material.setParameter(ParamId::Shininess, 2.0);
  preset.material.setParameter(ParamId::NormalStrength, 0.8);
  return preset;
}

}  // namespace relief::core
