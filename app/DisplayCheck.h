// Checks that a display can be reached before Qt's platform plugin starts: Qt aborts the
// process when it cannot connect to X, and we want a sentence that says what to do instead.
// Platforms without OpenGL (offscreen, minimal) are refused the same way.
#pragma once

#include <string>

namespace relief::app {

// Empty when a display is reachable; otherwise the reason, in words.
std::string displayProblem();

}  // namespace relief::app
