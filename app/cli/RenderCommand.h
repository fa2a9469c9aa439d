// `relief-cli render`: renders a preset (or individual maps) offscreen through the same
// renderer as the viewport and writes the image.
#pragma once

namespace relief::cli {

// Takes argc/argv because rendering needs a QGuiApplication, created only after the command
// line is valid and a display is known to be reachable.
int runRender(int argc, char* argv[]);

}  // namespace relief::cli
