// Per-vertex tangent frames as reference 004 (Dachsbacher, "Parallax Bump Mapping") derives
// them: per-triangle tangent and bitangent from the UV derivatives, accumulated per vertex,
// Gram-Schmidt orthogonalised against the vertex normal, handedness stored in tangent.w.
#pragma once

#include "core/mesh/Mesh.h"

namespace relief::core::inline mesh {

// Recomputes every vertex's tangent from positions, normals and UVs. Triangles whose UVs are
// degenerate (zero area in UV space) contribute nothing; a vertex left without a usable
// tangent gets one perpendicular to its normal, so no NaN ever reaches the shader.
// Computes the UV scales too (computeUvScales).
void computeTangentFrames(Mesh& mesh);

// Sets every vertex's uvScale: the lengths of dP/du and dP/dv of the triangles around it
// (reference 004's per-triangle T and B before normalisation), averaged. Vertices of degenerate
// triangles only keep 0.
void computeUvScales(Mesh& mesh);

}  // namespace relief::core::inline mesh
