// HeightField: a material's height map as the renderer sees it, for exact CPU computations.
// Heights are in UV units above the mesh surface: s = h * heightScale + heightBias (h from the
// height map or the normal map's alpha, inverted for depth maps). Texels sit at their centres,
// rows count up from the bottom (v = 0) exactly as the GPU samples the uploaded texture, and
// between texels the field is bilinear, as GL_LINEAR filtering makes it.
#pragma once

#include "core/image/Image.h"
#include "core/material/Material.h"

#include <glm/glm.hpp>

#include <vector>

namespace relief::core::inline tracing {

class HeightField {
 public:
  // `channel` picks the height channel (0, or 3 for height packed in a normal map's alpha).
  // The field repeats outside [0, 1) like a GL_REPEAT texture.
  HeightField(const Image& image, int channel, double heightScale, double heightBias,
              bool heightIsDepth);

  // The height field of a material's current maps and parameters, or an empty field (all
  // texels at the top) when it has no height.
  static HeightField fromMaterial(const Material& material);

  int width() const { return m_width; }
  int height() const { return m_height; }
  // Height of texel (i, j) in UV units; j counts rows from the bottom; indices wrap.
  double texel(int i, int j) const;
  // Bilinear height at texture coordinates (u, v), repeating.
  double sample(double u, double v) const;
  double minimum() const { return m_minimum; }
  double maximum() const { return m_maximum; }

 private:
  int m_width = 1;
  int m_height = 1;
  std::vector<double> m_heights;  // row 0 = bottom
  double m_minimum = 0.0;
  double m_maximum = 0.0;
};

}  // namespace relief::core::inline tracing
