// Height maps from normal maps: Frankot-Chellappa integration. The normals give the height's
// gradient (dh/dx = -nx/nz, dh/dy = -ny/nz); the height whose gradient is closest to it in the
// least-squares sense is solved in the Fourier domain, H = -i(wx Gx + wy Gy) / (wx^2 + wy^2),
// with FFTW. The FFT assumes a periodic field: tileable maps are integrated as they are, others
// are mirror-padded to twice their size first so no slope wraps around.
#pragma once

#include "core/base/Result.h"
#include "core/base/WorkControl.h"
#include "core/generators/ImageFilters.h"
#include "core/generators/NormalFromHeight.h"
#include "core/image/Image.h"

namespace relief::core::inline generators {

struct HeightFromNormalOptions {
  NormalConvention convention = NormalConvention::OpenGl;  // of the input
  EdgeMode edge = EdgeMode::Clamp;  // Wrap: periodic (tileable). Clamp: mirror-padded.
};

struct HeightFromNormalResult {
  Image height;              // 1 channel, normalised to [0, 1]
  double rangeTexels = 0.0;  // the relief's depth before normalising, in texel widths
};

// Fails only when cancelled. Normals pointing into the surface are clamped to a steep slope.
Result<HeightFromNormalResult> heightFromNormal(const Image& normals,
                                                const HeightFromNormalOptions& options,
                                                const WorkControl& control = {});

}  // namespace relief::core::inline generators
