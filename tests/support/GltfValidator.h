// Runs the Khronos glTF validator (installed by tools/gltf-validator/setup.sh into the build
// folder) on a .gltf file. When the validator is not installed, says why, so the caller can
// skip with that reason instead of passing.
#pragma once

#include <string>

namespace relief::test {

struct GltfValidation {
  bool available = false;
  std::string unavailableReason;
  int errors = 0;
  int warnings = 0;
  std::string report;  // the validator's JSON report (or what node printed on failure)
};

GltfValidation validateGltf(const std::string& gltfPath);

}  // namespace relief::test
