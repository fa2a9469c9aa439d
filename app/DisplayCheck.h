// Checks that an X display can be reached before Qt's xcb platform is started: Qt aborts the
// process when it cannot connect, and we want a sentence that says what to do instead.
#pragma once

#include <string>

namespace relief::app {

// Empty when a display is reachable; otherwise the reason, in words.
std::string displayProblem();

}  // namespace relief::app
