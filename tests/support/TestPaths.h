// Where tests find the source tree (samples, baselines) and where they may write.
#pragma once

#include <string>

namespace relief::test {

std::string sourcePath(const std::string& relative);  // e.g. "samples/bricks/bricks.relief"
std::string samplePreset(const std::string& name);    // samples/<name>/<name>.relief
std::string binaryPath(const std::string& relative);  // under the build folder
// A fresh, empty folder for this test process under the build tree.
std::string scratchFolder();
// Where failed image comparisons leave their actual and difference images.
std::string failureOutputFolder();

}  // namespace relief::test
