// Meshes made for tests, shared by the core and the render tests.
#pragma once

#include "core/mesh/Mesh.h"

namespace relief::test {

// Two quads side by side sharing no vertices, the right one's u running backwards (a mirrored UV
// island, as on symmetric models), with tangent frames computed.
core::Mesh mirroredQuads();

}  // namespace relief::test
