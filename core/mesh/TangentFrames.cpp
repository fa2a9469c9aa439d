// Tangent frames after reference 004; see TangentFrames.h.
#include "core/mesh/TangentFrames.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace relief::core::inline mesh {
namespace {

// Reference 004's fallback: A = (ny, -nz, nx) is never parallel to N (unless N is zero), so
// T = N x A is a valid tangent. We orthogonalise it like the others.
glm::vec3 fallbackTangent(const glm::vec3& n) {
  const glm::vec3 a(n.y, -n.z, n.x);
  glm::vec3 t = glm::cross(n, a);
  if (glm::dot(t, t) < 1e-12f)
    t = glm::vec3(1.0f, 0.0f, 0.0f);
  return glm::normalize(t);
}

// Reference 004's per-triangle dP/du (T) and dP/dv (B): P = V - U, Q = W - U, (s1, t1) and
// (s2, t2) their UV differences; [T; B] = 1 / (s1 t2 - s2 t1) * [t2 -t1; -s2 s1] * [P; Q].
// False for degenerate UVs (the system has no solution; skipping keeps NaN and infinities out).
bool triangleDerivatives(const Mesh& mesh, std::size_t first, glm::vec3& t, glm::vec3& b) {
  const Vertex& u = mesh.vertices[mesh.indices[first]];
  const Vertex& v = mesh.vertices[mesh.indices[first + 1]];
  const Vertex& w = mesh.vertices[mesh.indices[first + 2]];
  const glm::vec3 p = v.position - u.position;
  const glm::vec3 q = w.position - u.position;
  const float s1 = v.uv.x - u.uv.x, t1 = v.uv.y - u.uv.y;
  const float s2 = w.uv.x - u.uv.x, t2 = w.uv.y - u.uv.y;
  const float det = s1 * t2 - s2 * t1;
  // The threshold is relative to the UV extent so tiny but valid triangles still count.
  const float uvScale = std::max({std::abs(s1), std::abs(t1), std::abs(s2), std::abs(t2)});
  if (!(std::abs(det) > 1e-12f * uvScale * uvScale) || !std::isfinite(det))
    return false;
  const float r = 1.0f / det;
  t = (p * t2 - q * t1) * r;
  b = (q * s1 - p * s2) * r;
  return std::isfinite(glm::dot(t, t)) && std::isfinite(glm::dot(b, b));
}

}  // namespace

void computeUvScales(Mesh& mesh) {
  const std::size_t count = mesh.vertices.size();
  std::vector<glm::vec2> sums(count, glm::vec2(0.0f));
  std::vector<int> triangles(count, 0);
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    glm::vec3 t, b;
    if (!triangleDerivatives(mesh, i, t, b))
      continue;
    for (std::size_t corner = i; corner < i + 3; ++corner) {
      sums[mesh.indices[corner]] += glm::vec2(glm::length(t), glm::length(b));
      ++triangles[mesh.indices[corner]];
    }
  }
  for (std::size_t i = 0; i < count; ++i)
    mesh.vertices[i].uvScale = triangles[i] > 0 ? sums[i] / float(triangles[i]) : glm::vec2(0.0f);
}

void computeTangentFrames(Mesh& mesh) {
  const std::size_t count = mesh.vertices.size();
  std::vector<glm::vec3> tangents(count, glm::vec3(0.0f));
  std::vector<glm::vec3> bitangents(count, glm::vec3(0.0f));

  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    glm::vec3 t, b;
    if (!triangleDerivatives(mesh, i, t, b))
      continue;
    for (std::size_t corner = i; corner < i + 3; ++corner) {
      tangents[mesh.indices[corner]] += t;
      bitangents[mesh.indices[corner]] += b;
    }
  }

  for (std::size_t i = 0; i < count; ++i) {
    Vertex& vertex = mesh.vertices[i];
    glm::vec3 n = vertex.normal;
    const float nLength = glm::length(n);
    n = nLength > 1e-12f && std::isfinite(nLength) ? n / nLength : glm::vec3(0.0f, 0.0f, 1.0f);
    vertex.normal = n;
    // Gram-Schmidt: T.xyz = T - (N . T) N, then normalise.
    glm::vec3 t = tangents[i] - glm::dot(n, tangents[i]) * n;
    const float tLength = glm::length(t);
    if (tLength > 1e-8f && std::isfinite(tLength)) {
      t /= tLength;
    } else if (glm::dot(bitangents[i], bitangents[i]) > 1e-16f) {
      // Only the bitangent survived (e.g. UVs that vary in one direction): T = B x N.
      t = glm::cross(bitangents[i], n);
      t = glm::dot(t, t) > 1e-16f ? glm::normalize(t) : fallbackTangent(n);
    } else {
      t = fallbackTangent(n);
    }
    // Handedness: T.w = (N x T) . B < 0 ? -1 : 1.
    const float w = glm::dot(glm::cross(n, t), bitangents[i]) < 0.0f ? -1.0f : 1.0f;
    vertex.tangent = glm::vec4(t, w);
  }
  computeUvScales(mesh);
}

}  // namespace relief::core::inline mesh
