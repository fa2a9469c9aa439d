// AdaptiveResolution; see AdaptiveResolution.h.
#include "ui/viewport/AdaptiveResolution.h"

#include <algorithm>
#include <cmath>

namespace relief::ui::inline viewport {

void AdaptiveResolution::recordFrame(double milliseconds, double pixels) {
  if (pixels <= 0.0 || !(milliseconds >= 0.0))
    return;
  const double sample = milliseconds / pixels;
  // Half the weight on the newest frame: one slow frame (a texture upload) is forgotten after a
  // few frames, and a real change of cost (a heavier technique) is followed within two.
  m_msPerPixel = m_msPerPixel > 0.0 ? 0.5 * (m_msPerPixel + sample) : sample;
}

float AdaptiveResolution::nextInteractiveScale(double fullPixels) {
  if (m_msPerPixel <= 0.0 || fullPixels <= 0.0)
    return m_scale = 1.0f;
  // Cost ~ msPerPixel * fullPixels * scale^2 <= budget.
  const double ideal = std::sqrt(m_budgetMs / (m_msPerPixel * fullPixels));
  const float step = 1.0f / float(kScaleSteps);
  const float quantised =
      std::clamp(float(std::floor(ideal * kScaleSteps)) * step, kMinimumScale, 1.0f);
  if (quantised < m_scale || quantised >= std::min(m_scale + 2.0f * step, 1.0f))
    m_scale = quantised;
  return m_scale;
}

int AdaptiveResolution::rowsWithinBudget(int width, int height, int maxBands) const {
  const int fewest = (height + maxBands - 1) / std::max(maxBands, 1);
  if (m_msPerPixel <= 0.0)
    return height;
  const double rows = m_budgetMs / (m_msPerPixel * double(std::max(width, 1)));
  return std::clamp(int(rows), std::max(fewest, 1), std::max(height, 1));
}

}  // namespace relief::ui::inline viewport
