// Curvature maps (convex/concave) from a height or a normal map: mid-grey is flat, brighter is
// convex (ridges, dome tops), darker concave (creases, pits). From height it is minus the
// Laplacian; from normals the divergence of the normal's tangent-plane part. Used as a mask
// for edge wear and cavity dirt.
#pragma once

#include "core/base/WorkControl.h"
#include "core/generators/ImageFilters.h"
#include "core/generators/NormalFromHeight.h"
#include "core/image/Image.h"

namespace relief::core::inline generators {

enum class CurvatureSource { Height, Normal };

struct CurvatureOptions {
  CurvatureSource source = CurvatureSource::Height;
  double strength = 4.0;    // gain around mid-grey
  double blurRadius = 1.0;  // texels (Gaussian sigma) before differentiating; 0 = none
  NormalConvention convention = NormalConvention::OpenGl;  // of a normal-map source
  EdgeMode edge = EdgeMode::Wrap;
  double texelScale = 1.0;
};

Image curvatureMap(const Image& source, const CurvatureOptions& options,
                   const WorkControl& control = {});

}  // namespace relief::core::inline generators
