// Built-in meshes: plane, cube and sphere with UVs and tangent frames (computeTangentFrames).
// UVs follow OpenGL: v grows upward in the image, so a normal map's +Y points "up the texture".
#pragma once

#include "core/mesh/Mesh.h"

#include <optional>
#include <span>
#include <string_view>

namespace relief::core::inline mesh {

enum class PrimitiveShape { Plane, Cube, Sphere, Cylinder, Torus };

std::span<const PrimitiveShape> allPrimitiveShapes();
std::string_view primitiveShapeName(PrimitiveShape shape);  // "plane", "cube", ...
std::optional<PrimitiveShape> findPrimitiveShape(std::string_view name);

// A size x size square in the XZ plane facing +Y; u along +X, v along -Z (away from a viewer
// on the +Z side), so that the texture reads upright when seen from the default camera.
Mesh makePlane(float size = 2.0f, int segments = 1);
// An axis-aligned cube centred on the origin; every face carries the full 0..1 UV square,
// upright on the side faces, as a grid of segments x segments quads.
Mesh makeCube(float size = 1.6f, int segments = 1);
// A UV sphere: u is longitude (increasing to the right seen from outside), v latitude.
Mesh makeSphere(float radius = 1.0f, int segments = 96, int rings = 48);
// A capped cylinder along Y. The side's u runs around (twice, so texels stay near square at
// the default proportions) and v up; the caps are mapped as flat discs.
Mesh makeCylinder(float radius = 0.8f, float height = 2.0f, int segments = 96);
// A torus around Y: u along the ring (three repeats), v around the tube.
Mesh makeTorus(float ringRadius = 1.0f, float tubeRadius = 0.4f, int ringSegments = 128,
               int tubeSegments = 48);

// The flat faces of the primitives the editor and the CLI show are grids of this many quads a
// side: the displacement technique splits each triangle edge into at most 64 segments (the
// least GL_MAX_TESS_GEN_LEVEL a GL 4 driver offers), so a 16 x 16 grid lets it reach a
// 1024-texel map's texels. The other techniques draw the same pixels either way.
constexpr int kPrimitiveFaceSegments = 16;

Mesh makePrimitive(PrimitiveShape shape);

}  // namespace relief::core::inline mesh
