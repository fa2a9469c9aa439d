// HeightField; see HeightField.h.
#include "core/tracing/HeightField.h"

#include <algorithm>
#include <cmath>

namespace relief::core::inline tracing {

HeightField::HeightField(const Image& image, int channel, double heightScale, double heightBias,
                         bool heightIsDepth)
    : m_width(image.width()), m_height(image.height()) {
  channel = std::min(channel, image.channels() - 1);
  m_heights.resize(std::size_t(m_width) * std::size_t(m_height));
  m_minimum = 1e300;
  m_maximum = -1e300;
  for (int j = 0; j < m_height; ++j) {
    for (int i = 0; i < m_width; ++i) {
      double h = image.at(i, m_height - 1 - j, channel);
      if (heightIsDepth)
        h = 1.0 - h;
      const double s = h * heightScale + heightBias;
      m_heights[std::size_t(j) * std::size_t(m_width) + std::size_t(i)] = s;
      m_minimum = std::min(m_minimum, s);
      m_maximum = std::max(m_maximum, s);
    }
  }
}

HeightField HeightField::fromMaterial(const Material& material) {
  const double scale = material.parameter(ParamId::HeightScale);
  const double bias = material.parameter(ParamId::HeightBias);
  const bool depth = material.parameterFlag(ParamId::HeightIsDepth);
  if (material.parameterFlag(ParamId::HeightInNormalAlpha) && material.hasMap(MapSlot::Normal) &&
      material.image(MapSlot::Normal)->channels() == 4) {
    return HeightField(*material.image(MapSlot::Normal), 3, scale, bias, depth);
  }
  if (material.hasMap(MapSlot::Height)) {
    return HeightField(*material.image(MapSlot::Height), 0, scale, bias, depth);
  }
  // No height: the neutral texture the renderer binds is the top surface (h = 1).
  Image top(1, 1, 1);
  top.at(0, 0, 0) = 1.0f;
  return HeightField(top, 0, scale, bias, false);
}

double HeightField::texel(int i, int j) const {
  i = ((i % m_width) + m_width) % m_width;
  j = ((j % m_height) + m_height) % m_height;
  return m_heights[std::size_t(j) * std::size_t(m_width) + std::size_t(i)];
}

double HeightField::sample(double u, double v) const {
  const double x = u * m_width - 0.5;
  const double y = v * m_height - 0.5;
  const double fx = std::floor(x);
  const double fy = std::floor(y);
  const auto i = int(fx);
  const auto j = int(fy);
  const double tx = x - fx;
  const double ty = y - fy;
  const double bottom = texel(i, j) * (1.0 - tx) + texel(i + 1, j) * tx;
  const double top = texel(i, j + 1) * (1.0 - tx) + texel(i + 1, j + 1) * tx;
  return bottom * (1.0 - ty) + top * ty;
}

}  // namespace relief::core::inline tracing
