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
  if (failed) {
    xcb_disconnect(connection);
    return std::string("cannot connect to the X display '") + display +
           "'; is the X server (or Xvfb) running?";
  }
  // The probe's connection stays open until the process ends. Closed now, it could be the
  // server's last client: X servers (Xvfb too) then reset, and a connection Qt opens during the
  // reset fails, which Qt answers with abort(). Renders run in parallel would hit this.
  static xcb_connection_t* kept = nullptr;
  if (kept)
    xcb_disconnect(connection);  // a second probe: one open connection is enough
  else
    kept = connection;
  return {};
}

}  // namespace relief::app
