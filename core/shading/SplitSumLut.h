// The split-sum table of image-based lighting (Karis, "Real Shading in Unreal Engine 4", 2013):
// the specular BRDF's directional albedo split into a scale and a bias on f0,
//   integral of f_spec(l, v) (N.L) dl = f0 * A + B,
//   A = integral of (1 - Fc) D V (N.L) dl,  B = integral of Fc D V (N.L) dl,  Fc = (1 - V.H)^5,
// for the glTF BRDF's GGX and height-correlated Smith terms (Brdf.h), tabulated over N.V and
// perceptual roughness. A + B is the energy a single scattering keeps (1 for a mirror); the
// shader adds the lost rest back as multiple scattering (Fdez-Agüera, "A Multiple-Scattering
// Microfacet Model for Real-Time Image-based Lighting", JCGT 2019).
#pragma once

#include "core/image/Image.h"

namespace relief::core::inline shading {

struct SplitSumTerms {
  float scale = 0.0f;  // A: the factor on f0
  float bias = 0.0f;   // B: added to it
};

// A and B at one N.V and perceptual roughness, by importance sampling the GGX distribution of
// normals with `samples` points of the Hammersley sequence.
SplitSumTerms integrateSplitSum(float nDotV, float roughness, int samples);

// The table: `size` x `size` texels of (A, B) in channels 0 and 1 (2 and 3 zero), column i at
// N.V = (i + 0.5) / size, row j at roughness = (j + 0.5) / size (row 0 first, smooth). Sampling
// it bilinearly at (N.V, roughness) interpolates between those centres.
Image makeSplitSumLut(int size, int samples);

}  // namespace relief::core::inline shading
