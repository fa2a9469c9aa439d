// Material: the document an artist edits. The maps (colour, normal, height; AO and roughness
// optional), the technique and the parameter values. Plain data with value semantics; maps are
// shared immutable images, so copying a material (for undo, for a render thread) is cheap.
#pragma once

#include "core/image/Image.h"
#include "core/material/MapSlot.h"
#include "core/material/Parameters.h"
#include "core/material/Technique.h"

#include <memory>
#include <string>

namespace relief::core::inline compression {
struct CompressedTexture;
}

namespace relief::core::inline material {

struct MaterialMap {
  std::shared_ptr<const Image> image;  // null when the slot is empty
  std::string sourcePath;              // the file it came from; empty for generated maps
  int sourceChannel = -1;  // the file's channel it is (0..3, an ORM texture's), or -1: all of it
  // A compression preview: the GPU blocks, with `image` their decoded map (for everything that
  // reads texels on the CPU). The renderer uploads the blocks natively when it can.
  std::shared_ptr<const CompressedTexture> compressed;
};

class Material {
 public:
  Material();

  const std::string& name() const { return m_name; }
  void setName(std::string name) { m_name = std::move(name); }

  const MaterialMap& map(MapSlot slot) const { return m_maps[std::size_t(slot)]; }
  const Image* image(MapSlot slot) const { return map(slot).image.get(); }
  bool hasMap(MapSlot slot) const { return image(slot) != nullptr; }
  // The image is tagged with the slot's colour space (colour sRGB, the rest linear).
  void setMap(MapSlot slot, std::shared_ptr<const Image> image, std::string sourcePath = {},
              int sourceChannel = -1);
  void clearMap(MapSlot slot) { m_maps[std::size_t(slot)] = {}; }
  // Replaces a slot's map by a compressed version of it (`decoded` is its decoded map); the
  // source path stays, so the material still names where the original came from.
  void setCompressedMap(MapSlot slot, std::shared_ptr<const CompressedTexture> texture,
                        std::shared_ptr<const Image> decoded);

  Technique technique() const { return m_technique; }
  void setTechnique(Technique technique) { m_technique = technique; }

  double parameter(ParamId id) const { return m_parameters[std::size_t(id)]; }
  float parameterf(ParamId id) const { return float(parameter(id)); }
  bool parameterFlag(ParamId id) const { return parameter(id) != 0.0; }
  // Clamps to the declared range (see sanitizeOptionValue).
  void setParameter(ParamId id, double value);
  const ParameterValues& parameters() const { return m_parameters; }

 private:
  std::string m_name;
  std::array<MaterialMap, kMapSlotCount> m_maps;
  Technique m_technique = Technique::Normal;
  ParameterValues m_parameters;
};

}  // namespace relief::core::inline material
