// Checks a glTF 2.0 file (.gltf JSON or .glb binary) before Assimp reads it, for what Assimp
// handles badly: a node hierarchy nested deeply enough to overflow its recursion (SIGSEGV),
// buffer and image URIs that point outside the file's folder (../../etc/passwd read as vertex
// data), and .glb chunk lengths that claim more than the file holds (seconds of work before a
// refusal). Other formats pass untouched.
#pragma once

#include "core/base/Result.h"

#include <string>

namespace relief::core::inline mesh {

// The deepest node hierarchy and the most nodes a mesh file may have.
inline constexpr int kMaxNodeDepth = 256;
inline constexpr int kMaxNodeCount = 100000;

// Fails with a message naming the file and the problem; passes files that are not glTF.
Status preflightGltf(const std::string& path);

}  // namespace relief::core::mesh
