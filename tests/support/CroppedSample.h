// A bundled sample cut down to a small corner, for tests that run whole pipelines (the chooser
// compresses and renders every candidate) and need them to take seconds, not minutes.
#pragma once

#include <string>

namespace relief::test {

// Writes `folder`/<sample>_cut.relief: the sample's preset (parameters, technique) with each of
// its maps replaced by its top-left `size` x `size` texels (16-bit PNG); returns the path.
std::string croppedSamplePreset(const std::string& sample, int size, const std::string& folder);

}  // namespace relief::test
