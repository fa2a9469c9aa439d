// ReliefTracer; see ReliefTracer.h.
#include "core/tracing/ReliefTracer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace relief::core::inline tracing {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

enum class Crossing {
  AtOrAbove,      // view rays: first point where the surface is at or above the ray
  StrictlyAbove,  // shadow rays: first point where the surface rises above the ray
};

// A ray in texel-centre space: x = u * W - 0.5 (texel i's centre at x = i), same for y;
// s is the height in UV units.
struct GridRay {
  double x0, y0, s0;
  double dx, dy, ds;
  double x(double t) const { return x0 + dx * t; }
  double y(double t) const { return y0 + dy * t; }
  double s(double t) const { return s0 + ds * t; }
};

// g(tau) = surface - ray inside one cell, as c0 + c1 tau + c2 tau^2 (tau measured from the
// cell's entry), plus the bilinear coefficients for exact evaluation.
struct CellFunction {
  double c0, c1, c2;
  double value(double tau) const { return c0 + tau * (c1 + tau * c2); }
  double slope(double tau) const { return c1 + 2.0 * c2 * tau; }
};

CellFunction cellFunction(const HeightField& field, const GridRay& ray, int i, int j,
                          double tEntry) {
  const double a = field.texel(i, j);
  const double b = field.texel(i + 1, j) - a;
  const double c = field.texel(i, j + 1) - a;
  const double d = field.texel(i + 1, j + 1) - field.texel(i + 1, j) - field.texel(i, j + 1) + a;
  const double px = ray.x(tEntry) - i;
  const double py = ray.y(tEntry) - j;
  CellFunction g;
  g.c0 = a + b * px + c * py + d * px * py - ray.s(tEntry);
  g.c1 = b * ray.dx + c * ray.dy + d * (px * ray.dy + py * ray.dx) - ray.ds;
  g.c2 = d * ray.dx * ray.dy;
  return g;
}

// Real roots of c0 + c1 t + c2 t^2 in ascending order (0, 1 or 2 of them), computed with the
// cancellation-free form of the quadratic formula.
int quadraticRoots(const CellFunction& g, double roots[2]) {
  const double scale = std::max({std::abs(g.c0), std::abs(g.c1), std::abs(g.c2), 1e-300});
  if (std::abs(g.c2) <= 1e-14 * scale) {
    if (std::abs(g.c1) <= 1e-300)
      return 0;
    roots[0] = -g.c0 / g.c1;
    return 1;
  }
  const double discriminant = g.c1 * g.c1 - 4.0 * g.c2 * g.c0;
  if (discriminant < 0.0)
    return 0;
  const double q = -0.5 * (g.c1 + std::copysign(std::sqrt(discriminant), g.c1));
  double r1 = q / g.c2;
  double r2 = q != 0.0 ? g.c0 / q : r1;
  if (r1 > r2)
    std::swap(r1, r2);
  roots[0] = r1;
  roots[1] = r2;
  return 2;
}

// Narrows [low, high] (g(low) below the threshold, g(high) at or above it) by bisection until
// the bracket is far below a texel, so the result does not depend on the root formula's
// rounding.
double polish(const CellFunction& g, double low, double high, bool strict) {
  for (int i = 0; i < 60 && high - low > 1e-15; ++i) {
    const double mid = 0.5 * (low + high);
    const bool above = strict ? g.value(mid) > 0.0 : g.value(mid) >= 0.0;
    (above ? high : low) = mid;
  }
  return high;
}

// First tau in [0, length] where the surface meets (or, strictly, rises above) the ray, or -1.
double firstCrossingInCell(const CellFunction& g, double length, Crossing mode) {
  const bool strict = mode == Crossing::StrictlyAbove;
  if (!strict && g.value(0.0) >= 0.0)
    return 0.0;
  if (strict && (g.value(0.0) > 1e-12 || (g.value(0.0) >= -1e-12 && g.slope(0.0) > 0.0))) {
    return 0.0;
  }
  double roots[2];
  const int count = quadraticRoots(g, roots);
  // Candidate intervals between the roots; the first sample that is above marks the crossing.
  double previous = 0.0;
  for (int k = 0; k <= count; ++k) {
    const double next = k < count ? std::clamp(roots[k], 0.0, length) : length;
    if (next < previous)
      continue;
    const double probe = k < count ? std::min(next + 1e-12 * (1.0 + length), length) : next;
    const bool above = strict ? g.value(probe) > 0.0 : g.value(probe) >= 0.0;
    if (above && probe > 0.0)
      return polish(g, previous, probe, strict);
    previous = next;
  }
  return -1.0;
}

// Walks the texel-centre grid from tStart to tEnd and returns the first crossing's t, or NaN.
double firstCrossing(const HeightField& field, const GridRay& ray, double tStart, double tEnd,
                     Crossing mode, int& cellsVisited) {
  double t = tStart;
  // The cell at t, choosing the one the ray moves into when it starts on a boundary.
  const auto cellIndex = [](double coordinate, double direction) {
    double cell = std::floor(coordinate);
    if (coordinate == cell && direction < 0.0)
      cell -= 1.0;
    return int(cell);
  };
  int i = cellIndex(ray.x(t), ray.dx);
  int j = cellIndex(ray.y(t), ray.dy);
  const int stepI = ray.dx > 0.0 ? 1 : -1;
  const int stepJ = ray.dy > 0.0 ? 1 : -1;
  const double spanX = std::abs(ray.dx) * (tEnd - tStart);
  const double spanY = std::abs(ray.dy) * (tEnd - tStart);
  const int maxCells = int(std::min(spanX + spanY, 1e7)) + 4;
  for (int visited = 0; visited < maxCells && t < tEnd; ++visited) {
    ++cellsVisited;
    const double exitX = ray.dx == 0.0 ? kInfinity : ((i + (ray.dx > 0 ? 1 : 0)) - ray.x0) / ray.dx;
    const double exitY = ray.dy == 0.0 ? kInfinity : ((j + (ray.dy > 0 ? 1 : 0)) - ray.y0) / ray.dy;
    const double exit = std::min({exitX, exitY, tEnd});
    const CellFunction g = cellFunction(field, ray, i, j, t);
    const double tau = firstCrossingInCell(g, std::max(exit - t, 0.0), mode);
    if (tau >= 0.0)
      return t + tau;
    if (exit >= tEnd)
      break;
    if (exitX <= exitY)
      i += stepI;
    if (exitY <= exitX)
      j += stepJ;
    t = std::max(t, exit);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

GridRay makeRay(const HeightField& field, glm::dvec2 uv, double height, glm::dvec3 direction) {
  GridRay ray;
  ray.x0 = uv.x * field.width() - 0.5;
  ray.y0 = uv.y * field.height() - 0.5;
  ray.s0 = height;
  ray.dx = direction.x * field.width();
  ray.dy = direction.y * field.height();
  ray.ds = direction.z;
  return ray;
}

}  // namespace

ViewRayHit traceViewRay(const HeightField& field, glm::dvec2 entryUv, glm::dvec3 viewTangent) {
  ViewRayHit result;
  if (!(viewTangent.z > 1e-9))
    return result;
  // Along -V from the mesh surface (height 0): s(t) = -V.z t. Start where the ray is at the
  // field's top (t < 0 when the relief rises above the surface), end at its bottom.
  const GridRay ray = makeRay(field, entryUv, 0.0, -viewTangent);
  const double tStart = -field.maximum() / viewTangent.z;
  const double tEnd = -field.minimum() / viewTangent.z;
  const double t =
      firstCrossing(field, ray, tStart, tEnd + 1e-12, Crossing::AtOrAbove, result.cellsVisited);
  if (std::isnan(t))
    return result;
  result.hit = true;
  result.uv = entryUv - glm::dvec2(viewTangent.x, viewTangent.y) * t;
  result.height = -viewTangent.z * t;
  return result;
}

ShadowRayHit traceShadowRay(const HeightField& field, glm::dvec2 uv, double height,
                            glm::dvec3 lightTangent) {
  ShadowRayHit result;
  if (!(lightTangent.z > 1e-9)) {
    result.occluded = true;  // the light is at or below the horizon
    return result;
  }
  const GridRay ray = makeRay(field, uv, height, lightTangent);
  const double tEnd = (field.maximum() - height) / lightTangent.z;
  if (tEnd <= 0.0)
    return result;
  int cells = 0;
  const double t = firstCrossing(field, ray, 0.0, tEnd, Crossing::StrictlyAbove, cells);
  if (!std::isnan(t)) {
    result.occluded = true;
    result.distance = t;
  }
  return result;
}

}  // namespace relief::core::inline tracing
