// DisplayCheck; see DisplayCheck.h.
#include "DisplayCheck.h"

#include <xcb/xcb.h>

#include <cstdlib>

namespace relief::app {

std::string displayProblem() {
  const std::string platform = std::getenv("QT_QPA_PLATFORM") ? std::getenv("QT_QPA_PLATFORM") : "";
  if (platform == "offscreen" || platform == "minimal" || platform == "vnc") {
    return "QT_QPA_PLATFORM=" + platform +
           " cannot give an OpenGL context; Relief needs a display (unset it, or run under "
           "xvfb-run)";
  }
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  const bool wantsWayland = platform.rfind("wayland", 0) == 0;
  if (wantsWayland || ((!display || !*display) && wayland && *wayland)) {
    // Qt reports its own Wayland problems clearly; nothing to pre-check.
    return {};
  }
  if (!display || !*display) {
    return "no display (DISPLAY is not set); on a headless machine run under xvfb-run, e.g. "
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
