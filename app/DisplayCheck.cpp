// DisplayCheck; see DisplayCheck.h.
#include "DisplayCheck.h"

#include <xcb/xcb.h>

#include <cstdlib>

namespace relief::app {

std::string displayProblem() {
  const char* platform = std::getenv("QT_QPA_PLATFORM");
  if (platform && std::string(platform) != "xcb") {
    return std::string("QT_QPA_PLATFORM=") + platform +
           " cannot give an OpenGL context; Relief needs an X display (unset it, or run under "
           "xvfb-run)";
  }
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) {
    return "no X display (DISPLAY is not set); run under xvfb-run on a headless machine, e.g. "
           "xvfb-run -a relief-cli render ...";
  }
  xcb_connection_t* connection = xcb_connect(display, nullptr);
  const bool failed = xcb_connection_has_error(connection) != 0;
  xcb_disconnect(connection);
  if (failed) {
    return std::string("cannot connect to the X display '") + display +
           "'; is the X server (or Xvfb) running?";
  }
  return {};
}

}  // namespace relief::app
