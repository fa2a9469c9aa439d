// Real photographs for encoder tests: scikit-image's (Debian's python3-skimage, which
// tools/install-deps.sh installs; not committed, their licences differ). Synthetic maps flatter
// encoders; these do not.
#pragma once

#include "core/image/Image.h"

#include <vector>

namespace relief::test {

// A size x size centre crop of each of five colour photographs (astronaut, coffee, chelsea,
// rocket, motorcycle_left). A photograph that does not load fails the calling test, naming the
// file and the package to install.
std::vector<core::Image> photographCrops(int size = 256);

// Three grey photographs of surfaces, whole (512x512): brick, grass and gravel, the textures a
// tileable material starts from. Failing to load one fails the calling test, as above.
std::vector<core::Image> surfacePhotographs();

// Six colour maps of a real game, whole (256x256): Extreme Tux Racer's terrain textures (rock,
// grass, mud, paving, pebbles, snowy rock; Debian's extremetuxracer-data, which
// tools/install-deps.sh installs), 8-bit RGB. Failing to load one fails the calling test, as above.
std::vector<core::Image> gameColourMaps();

}  // namespace relief::test
