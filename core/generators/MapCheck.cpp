// Maps that check each other; see MapCheck.h.
#include "core/generators/MapCheck.h"

#include "core/generators/ImageFilters.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>

namespace relief::core::inline generators {
namespace {

// The slopes (p, q) = (-nx / nz, -ny / nz) a normal map encodes, y as stored (up for OpenGL).
struct Slopes {
  int width = 0, height = 0;
  std::vector<float> pq;  // p, q per texel, interleaved as the height gradient's dx, dy
  double at(int component, int x, int y) const {
    x = (x + width) % width;  // wrap: the maps of a material tile
    y = (y + height) % height;
    return pq[2 * (std::size_t(y) * std::size_t(width) + std::size_t(x)) + std::size_t(component)];
  }
};

Slopes slopesOf(const Image& normal) {
  Slopes slopes;
  slopes.width = normal.width();
  slopes.height = normal.height();
  const std::size_t count = normal.pixelCount();
  slopes.pq.resize(2 * count);
  // A map stored in two channels (BC5, EAC RG11) loads with an empty blue: Z is rebuilt, as the
  // shader does, when blue says the normals point into the surface on average.
  double blue = 0.0;
  if (normal.channels() >= 3) {
    for (std::size_t i = 0; i < count; ++i)
      blue += normal.data()[i * std::size_t(normal.channels()) + 2];
  }
  const bool rebuildZ = normal.channels() < 3 || blue / double(count) < 0.25;
  for (std::size_t i = 0; i < count; ++i) {
    const float* texel = normal.data() + i * std::size_t(normal.channels());
    const double nx = 2.0 * texel[0] - 1.0, ny = 2.0 * texel[1] - 1.0;
    double nz = rebuildZ ? std::sqrt(std::max(0.0, 1.0 - nx * nx - ny * ny)) : 2.0 * texel[2] - 1.0;
    nz = std::max(nz, 0.05);  // a slope past 87 degrees says nothing more
    slopes.pq[2 * i] = float(-nx / nz);
    slopes.pq[2 * i + 1] = float(-ny / nz);
  }
  return slopes;
}

// Pearson's correlation of one component of two fields of two floats per texel; 0 when either
// is constant.
double correlation(const float* a, const float* b, std::size_t count, int component) {
  const double n = double(count);
  double meanA = 0.0, meanB = 0.0;
  for (std::size_t i = std::size_t(component); i < 2 * count; i += 2) {
    meanA += a[i];
    meanB += b[i];
  }
  meanA /= n;
  meanB /= n;
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (std::size_t i = std::size_t(component); i < 2 * count; i += 2) {
    const double da = a[i] - meanA, db = b[i] - meanB;
    ab += da * db;
    aa += da * da;
    bb += db * db;
  }
  return aa > 0.0 && bb > 0.0 ? ab / std::sqrt(aa * bb) : 0.0;
}

// The sign of a correlation strong enough to count, else 0.
int evidence(double correlation) {
  return correlation >= kAxisThreshold ? 1 : correlation <= -kAxisThreshold ? -1 : 0;
}

std::string signed2(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.2f", value);
  return text;
}

}  // namespace

Result<MapCheckResult> checkMaps(const Image& normal, const Image* height) {
  if (normal.isEmpty() || normal.channels() < 2) {
    return makeError("the normal map has " + std::to_string(normal.channels()) +
                     " channel(s); a normal map needs at least X and Y");
  }
  // A height map of another resolution (game data often pairs a 256^2 normal map with a 512^2
  // height map) is resized to the normal map's, if it covers the same shape.
  std::optional<Image> resized;
  if (height && (height->width() != normal.width() || height->height() != normal.height())) {
    if (std::int64_t(height->width()) * normal.height() !=
        std::int64_t(height->height()) * normal.width()) {
      return makeError("the normal map is " + std::to_string(normal.width()) + "x" +
                       std::to_string(normal.height()) + " and the height map " +
                       std::to_string(height->width()) + "x" + std::to_string(height->height()) +
                       ": maps of different shapes cannot cover the same surface");
    }
    resized = resizeImage(*height, normal.width(), normal.height());
    height = &*resized;
  }
  const Slopes slopes = slopesOf(normal);
  MapCheckResult result;

  // Curl with y up (rows run down the image): d/dy at row r is (row r-1 - row r+1) / 2.
  double curl = 0.0, flipped = 0.0;
  for (int y = 0; y < slopes.height; ++y) {
    for (int x = 0; x < slopes.width; ++x) {
      const double pY = 0.5 * (slopes.at(0, x, y - 1) - slopes.at(0, x, y + 1));
      const double qX = 0.5 * (slopes.at(1, x + 1, y) - slopes.at(1, x - 1, y));
      curl += (pY - qX) * (pY - qX);
      flipped += (pY + qX) * (pY + qX);
    }
  }
  const double texels = double(normal.pixelCount());
  result.curlAsStored = curl / texels;
  result.curlFlipped = flipped / texels;
  std::optional<NormalConvention> byCurl;
  if (result.curlAsStored + result.curlFlipped > 1e-12) {
    if (result.curlAsStored < kCurlRatioThreshold * result.curlFlipped)
      byCurl = NormalConvention::OpenGl;
    else if (result.curlFlipped < kCurlRatioThreshold * result.curlAsStored)
      byCurl = NormalConvention::DirectX;
  }
  result.convention = byCurl;
  if (!height)
    return result;

  const Image gradient = heightGradient(*height, GradientKernel::Sobel, EdgeMode::Wrap);
  const float* g = gradient.data();  // dh/dx, dh/dy (y up) per texel
  const float* pq = slopes.pq.data();
  const std::size_t count = normal.pixelCount();
  result.correlationX = correlation(pq, g, count, 0);
  result.correlationY = correlation(pq, g, count, 1);
  int signX = evidence(*result.correlationX), signY = evidence(*result.correlationY);
  result.pairMatches = std::max(std::abs(*result.correlationX), std::abs(*result.correlationY)) >=
                       kMapCheckThreshold;
  if (!result.pairMatches)
    signX = signY = 0;  // a weak likeness of another surface says nothing of signs
  if (signX != 0 && signY != 0) {
    result.convention = signX == signY ? NormalConvention::OpenGl : NormalConvention::DirectX;
    result.heightIsDepth = signX < 0;
  } else if (signX != 0) {
    result.heightIsDepth = signX < 0;  // X is the same in both conventions
  } else if (signY != 0 && byCurl) {
    // Y's sign is the product of the two flips; the curl says which convention it is.
    result.heightIsDepth = (signY < 0) != (*byCurl == NormalConvention::DirectX);
  }
  // The strength that would rebuild the normal map from the height map, signs as found.
  double along = 0.0, squares = 0.0;
  const double sx = signX < 0 ? -1.0 : 1.0, sy = signY < 0 ? -1.0 : 1.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double gx = g[2 * i], gy = g[2 * i + 1];
    along += sx * pq[2 * i] * gx + sy * pq[2 * i + 1] * gy;
    squares += gx * gx + gy * gy;
  }
  if (squares > 0.0 && result.pairMatches)
    result.strength = along / squares;
  return result;
}

std::vector<std::string> mapCheckFindings(const MapCheckResult& result,
                                          NormalConvention declaredConvention,
                                          bool declaredHeightIsDepth, const std::string& normalName,
                                          const std::string& heightName) {
  std::vector<std::string> findings;
  std::string correlations;
  if (result.correlationX && result.correlationY) {
    correlations = "the normal map's slopes correlate with the height map's by x " +
                   signed2(*result.correlationX) + ", y " + signed2(*result.correlationY);
  }
  char curlText[96];
  std::snprintf(curlText, sizeof curlText, "its curl as stored is %.2fx that with Y flipped",
                result.curlFlipped > 0.0 ? result.curlAsStored / result.curlFlipped : 1.0);
  if (!result.pairMatches) {
    findings.push_back(normalName + " and " + heightName + " do not describe the same surface: " +
                       correlations + " (a matching pair is near +1 or -1)");
  }
  if (result.convention && *result.convention != declaredConvention) {
    const bool directX = *result.convention == NormalConvention::DirectX;
    findings.push_back(
        normalName + " is a " + (directX ? "DirectX (+Y down)" : "OpenGL (+Y up)") +
        " normal map but the material reads it as " + (directX ? "OpenGL" : "DirectX") +
        ": flip its Y (normalYDown " + (directX ? "on" : "off") +
        "). Evidence: " + (correlations.empty() ? "" : correlations + "; ") + curlText);
  }
  if (result.heightIsDepth && *result.heightIsDepth != declaredHeightIsDepth) {
    const bool depth = *result.heightIsDepth;
    findings.push_back(
        heightName + " is inverted against " + normalName + ": it " +
        (depth ? "stores depth (white is deepest)" : "stores height (white is top)") +
        " but the material reads it as " + (depth ? "height" : "depth") + " (heightIsDepth " +
        (depth ? "on" : "off") + "). Evidence: " + correlations);
  }
  return findings;
}

}  // namespace relief::core::inline generators
