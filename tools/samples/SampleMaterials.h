// The procedural sample materials that ship in samples/: bricks, cobblestones and tiles.
// Each is tileable, built from one height field and a colour field designed together, with
// the relief depth (heightScale, in UV units) the normal map is baked for.
#pragma once

#include "core/image/Image.h"

#include <string>
#include <vector>

namespace relief::tools {

struct SampleMaterial {
  std::string name;
  core::Image colorLinear;    // RGB, linear light; encoded to sRGB when saved
  core::Image height;         // 1 channel, 1.0 = top surface
  double heightScale = 0.03;  // UV units spanned by heights 0..1
  double tiling = 2.0;
  double specular = 0.25;
  double shininess = 32.0;
};

SampleMaterial makeBricks(int size);
SampleMaterial makeCobblestones(int size);
SampleMaterial makeTiles(int size);

std::vector<SampleMaterial> makeAllSamples(int size);

}  // namespace relief::tools
