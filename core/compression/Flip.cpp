// FLIP; see Flip.h. The constants are the paper's (section 3 and its table of CSF parameters).
#include "core/compression/Flip.h"

#include "core/base/ParallelFor.h"
#include "core/image/PlaneConvolution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace relief::core::inline compression {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kQc = 0.7f, kQf = 0.5f, kPc = 0.4f, kPt = 0.95f;
constexpr double kFeatureWidthDegrees = 0.082;  // w: peak to trough of the edge filter
// D65 white in XYZ, the reference white of YyCxCz and L*a*b*.
constexpr std::array<float, 3> kWhite = {0.950428545f, 1.0f, 1.088900371f};

using Rgb = std::array<float, 3>;

struct Planes {
  int width = 0, height = 0;
  std::array<std::vector<float>, 3> values;
  float& at(int c, int x, int y) {
    return values[std::size_t(c)][std::size_t(y) * std::size_t(width) + std::size_t(x)];
  }
  float at(int c, int x, int y) const {
    return values[std::size_t(c)][std::size_t(y) * std::size_t(width) + std::size_t(x)];
  }
};

float srgbDecode(float v) {
  return v > 0.04045f ? std::pow((v + 0.055f) / 1.055f, 2.4f) : v / 12.92f;
}

Rgb linearToXyz(const Rgb& c) {
  return {0.4123908f * c[0] + 0.3575843f * c[1] + 0.1804808f * c[2],
          0.2126390f * c[0] + 0.7151687f * c[1] + 0.0721923f * c[2],
          0.0193308f * c[0] + 0.1191948f * c[1] + 0.9505322f * c[2]};
}

Rgb xyzToLinear(const Rgb& c) {
  return {3.2409699f * c[0] - 1.5373832f * c[1] - 0.4986108f * c[2],
          -0.9692436f * c[0] + 1.8759675f * c[1] + 0.0415551f * c[2],
          0.0556301f * c[0] - 0.2039770f * c[1] + 1.0569715f * c[2]};
}

// YyCxCz: CIELab without its cube root, the space where the eye's contrast sensitivity is
// applied as a filter.
Rgb xyzToOpponent(const Rgb& xyz) {
  const float x = xyz[0] / kWhite[0], y = xyz[1] / kWhite[1], z = xyz[2] / kWhite[2];
  return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

Rgb opponentToXyz(const Rgb& o) {
  const float y = (o[0] + 16.0f) / 116.0f;
  return {(y + o[1] / 500.0f) * kWhite[0], y * kWhite[1], (y - o[2] / 200.0f) * kWhite[2]};
}

// Hunt-adjusted L*a*b* of a linear RGB colour.
Rgb huntLab(const Rgb& linear) {
  const Rgb xyz = linearToXyz(linear);
  const auto f = [](float t) {
    constexpr float delta = 6.0f / 29.0f;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
  };
  const float fx = f(xyz[0] / kWhite[0]), fy = f(xyz[1] / kWhite[1]), fz = f(xyz[2] / kWhite[2]);
  const float l = 116.0f * fy - 16.0f;
  return {l, 0.01f * l * 500.0f * (fx - fy), 0.01f * l * 200.0f * (fy - fz)};
}

float hyab(const Rgb& a, const Rgb& b) {
  return std::abs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]);
}

// What a viewer sees of a texel: its first three channels as display values.
Rgb displayed(const Image& image, int x, int y) {
  const float* t = image.pixel(x, y);
  const auto clamp = [](float v) { return std::clamp(v, 0.0f, 1.0f); };
  switch (image.channels()) {
    case 1:
      return {clamp(t[0]), clamp(t[0]), clamp(t[0])};
    case 2:
      return {clamp(t[0]), clamp(t[1]), 0.0f};
    default:
      return {clamp(t[0]), clamp(t[1]), clamp(t[2])};
  }
}

Planes opponentPlanes(const Image& image) {
  Planes planes{image.width(), image.height(), {}};
  for (auto& plane : planes.values)
    plane.resize(image.pixelCount());
  parallelFor(image.height(), [&](int y) {
    for (int x = 0; x < image.width(); ++x) {
      Rgb c = displayed(image, x, y);
      for (float& v : c)
        v = srgbDecode(v);
      const Rgb o = xyzToOpponent(linearToXyz(c));
      for (int k = 0; k < 3; ++k)
        planes.at(k, x, y) = o[std::size_t(k)];
    }
  });
  return planes;
}

// Buffers reused across the filters: a 4096^2 map's planes are 64 MiB each, and allocating a
// fresh one per pass made zeroing and page faults half of the time.
struct Scratch {
  std::vector<float> between, result;
  explicit Scratch(std::size_t size) : between(size), result(size) {}
};

// `plane` along rows with `rows`, then along columns with `columns`, into scratch.result.
const std::vector<float>& separable(const std::vector<float>& plane, int width, int height,
                                    const std::vector<float>& rows,
                                    const std::vector<float>& columns, Scratch& scratch) {
  convolvePlane(plane.data(), scratch.between.data(), width, height, rows, true);
  convolvePlane(scratch.between.data(), scratch.result.data(), width, height, columns, false);
  return scratch.result;
}

// exp(-pi^2 x^2 / b), x in degrees, for |x| up to `radius` pixels; and its sum.
std::vector<float> csfGaussian(double b, int radius, double pixelsPerDegree, double& sum) {
  std::vector<float> kernel(std::size_t(2 * radius + 1));
  sum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    const double x = i / pixelsPerDegree;
    const double value = std::exp(-kPi * kPi * x * x / b);
    kernel[std::size_t(i + radius)] = float(value);
    sum += value;
  }
  return kernel;
}

std::vector<float> scaled(std::vector<float> kernel, double factor) {
  for (float& v : kernel)
    v = float(v * factor);
  return kernel;
}

// The colour pipeline's spatial filter, in place: each opponent channel convolved with its contrast
// sensitivity, S(x) = sum of a_i sqrt(pi / b_i) exp(-pi^2 x^2 / b_i) over the 2D kernel,
// normalised to sum 1 (achromatic a = 1, b = 0.0047; red-green a = 1, b = 0.0053; blue-yellow
// a = 34.1, b = 0.04 and a = 13.5, b = 0.025), within 3 standard deviations of the widest (b =
// 0.04); each Gaussian is separable. Then back to linear RGB, clamped to the unit cube, and on
// to Hunt-adjusted L*a*b*.
void filterToHuntLab(Planes& planes, double pixelsPerDegree, Scratch& scratch) {
  const int radius = int(std::ceil(3.0 * std::sqrt(0.04 / (2.0 * kPi * kPi)) * pixelsPerDegree));
  const int w = planes.width, h = planes.height;
  struct Term {
    double a, b;
  };
  const std::array<std::vector<Term>, 3> channels = {
      std::vector<Term>{{1.0, 0.0047}}, std::vector<Term>{{1.0, 0.0053}},
      std::vector<Term>{{34.1, 0.04}, {13.5, 0.025}}};
  std::vector<float> result(planes.values[0].size());
  for (std::size_t c = 0; c < 3; ++c) {
    // Term i contributes a_i sqrt(pi / b_i) S_i^2 to the 2D sum (S_i: its 1D sum).
    double total = 0.0;
    std::vector<std::vector<float>> kernels;
    std::vector<double> weights;
    for (const Term& term : channels[c]) {
      double sum = 0.0;
      std::vector<float> kernel = csfGaussian(term.b, radius, pixelsPerDegree, sum);
      const double weight = term.a * std::sqrt(kPi / term.b) * sum * sum;
      kernels.push_back(scaled(kernel, 1.0 / sum));
      weights.push_back(weight);
      total += weight;
    }
    for (std::size_t i = 0; i < kernels.size(); ++i) {
      const std::vector<float>& part =
          separable(planes.values[c], w, h, kernels[i], kernels[i], scratch);
      const float share = float(weights[i] / total);
      for (std::size_t p = 0; p < result.size(); ++p)
        result[p] = (i == 0 ? 0.0f : result[p]) + share * part[p];
    }
    std::swap(planes.values[c], result);
  }
  parallelFor(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      Rgb linear =
          xyzToLinear(opponentToXyz({planes.at(0, x, y), planes.at(1, x, y), planes.at(2, x, y)}));
      for (float& v : linear)
        v = std::clamp(v, 0.0f, 1.0f);
      const Rgb lab = huntLab(linear);
      for (int c = 0; c < 3; ++c)
        planes.at(c, x, y) = lab[std::size_t(c)];
    }
  });
}

// Edge and point strength of the achromatic channel (Y / Yn): the gradient and the second
// derivatives of a Gaussian whose standard deviation is half the feature width, each kernel's
// positive weights normalised to sum 1 and its negative ones to -1; the magnitude of the x and
// y responses.
struct Features {
  std::vector<float> edges, points;
};

Features features(const Planes& opponent, double pixelsPerDegree, Scratch& scratch) {
  const double sd = 0.5 * kFeatureWidthDegrees * pixelsPerDegree;
  const int radius = int(std::ceil(3.0 * sd));
  const std::size_t size = std::size_t(2 * radius + 1);
  std::vector<float> gauss(size), edge(size), point(size);
  double gaussSum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    const double g = std::exp(-double(i * i) / (2.0 * sd * sd));
    gauss[std::size_t(i + radius)] = float(g);
    edge[std::size_t(i + radius)] = float(-i * g);
    point[std::size_t(i + radius)] = float((double(i * i) / (sd * sd) - 1.0) * g);
    gaussSum += g;
  }
  // The 2D kernels are these times the Gaussian across, whose sum factors out of both the
  // positive and the negative weights' sums.
  const auto normalise = [](std::vector<float>& kernel) {
    double positive = 0.0, negative = 0.0;
    for (float v : kernel)
      (v > 0.0f ? positive : negative) += v;
    for (float& v : kernel)
      v = float(v > 0.0f ? v / positive : v / -negative);
  };
  normalise(edge);
  normalise(point);
  gauss = scaled(gauss, 1.0 / gaussSum);

  const int w = opponent.width, h = opponent.height;
  std::vector<float> y(opponent.values[0].size());
  for (std::size_t p = 0; p < y.size(); ++p)
    y[p] = (opponent.values[0][p] + 16.0f) / 116.0f;
  // Each magnitude accumulates x^2 + y^2 in place, then takes the root.
  Features result{std::vector<float>(y.size()), std::vector<float>(y.size())};
  const auto addSquares = [&](const std::vector<float>& response, std::vector<float>& into) {
    for (std::size_t p = 0; p < into.size(); ++p)
      into[p] += response[p] * response[p];
  };
  addSquares(separable(y, w, h, edge, gauss, scratch), result.edges);
  addSquares(separable(y, w, h, gauss, edge, scratch), result.edges);
  addSquares(separable(y, w, h, point, gauss, scratch), result.points);
  addSquares(separable(y, w, h, gauss, point, scratch), result.points);
  for (std::size_t p = 0; p < y.size(); ++p) {
    result.edges[p] = std::sqrt(result.edges[p]);
    result.points[p] = std::sqrt(result.points[p]);
  }
  return result;
}

// One image through both pipelines: its edge and point strengths, and its Hunt-adjusted L*a*b*
// after the contrast filters (the opponent planes filtered and converted in place).
struct Perceived {
  Planes lab;
  Features features;
};

Perceived perceive(const Image& image, double pixelsPerDegree, Scratch& scratch) {
  Perceived perceived{opponentPlanes(image), {}};
  perceived.features = features(perceived.lab, pixelsPerDegree, scratch);
  filterToHuntLab(perceived.lab, pixelsPerDegree, scratch);
  return perceived;
}

}  // namespace

FlipResult measureFlip(const Image& reference, const Image& test, double pixelsPerDegree,
                       bool keepComponents) {
  const int w = reference.width(), h = reference.height();
  Scratch scratch(reference.pixelCount());
  const Perceived ref = perceive(reference, pixelsPerDegree, scratch);
  const Perceived tst = perceive(test, pixelsPerDegree, scratch);
  scratch = Scratch(0);

  // The largest colour difference: pure green against pure blue, after Hunt's adjustment.
  const float cmax = std::pow(hyab(huntLab({0.0f, 1.0f, 0.0f}), huntLab({0.0f, 0.0f, 1.0f})), kQc);
  FlipResult result;
  result.errorMap = Image::forOverwrite(w, h, 1);
  if (keepComponents) {
    result.colourError = Image::forOverwrite(w, h, 1);
    result.featureError = Image::forOverwrite(w, h, 1);
  }
  parallelFor(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
      const Rgb a = {ref.lab.at(0, x, y), ref.lab.at(1, x, y), ref.lab.at(2, x, y)};
      const Rgb b = {tst.lab.at(0, x, y), tst.lab.at(1, x, y), tst.lab.at(2, x, y)};
      const float colour = std::pow(hyab(a, b), kQc);
      const float colourError =
          colour < kPc * cmax ? kPt / (kPc * cmax) * colour
                              : kPt + (colour - kPc * cmax) / (cmax - kPc * cmax) * (1.0f - kPt);
      const float featureChange =
          std::max(std::abs(ref.features.edges[p] - tst.features.edges[p]),
                   std::abs(ref.features.points[p] - tst.features.points[p]));
      const float featureError = kQf == 0.5f ? std::sqrt(featureChange / std::sqrt(2.0f))
                                             : std::pow(featureChange / std::sqrt(2.0f), kQf);
      result.errorMap.at(x, y, 0) = std::pow(colourError, 1.0f - featureError);
      if (keepComponents) {
        result.colourError.at(x, y, 0) = colourError;
        result.featureError.at(x, y, 0) = featureError;
      }
    }
  });
  std::vector<float> errors(result.errorMap.data(),
                            result.errorMap.data() + result.errorMap.valueCount());
  double sum = 0.0;
  for (float e : errors) {
    sum += e;
    result.maxError = std::max(result.maxError, double(e));
  }
  result.mean = errors.empty() ? 0.0 : sum / double(errors.size());
  if (!errors.empty()) {
    const std::size_t at = std::min(errors.size() - 1, std::size_t(0.95 * double(errors.size())));
    std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(at), errors.end());
    result.p95 = errors[at];
  }
  return result;
}

}  // namespace relief::core::inline compression
