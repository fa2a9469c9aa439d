// `relief-cli render` runs in a helper executable, relief-cli-render: rendering alone needs Qt
// GUI, OpenGL and X (46 more shared libraries to map), so the other commands start without them
// (docs/architecture.md, "Start-up"). The helper lies beside relief-cli in a build and in
// libexec/relief once installed.
#pragma once

namespace relief::cli {

// Replaces this process with the helper, given the same arguments (and --quiet when it was
// taken off the line). Returns only when the helper cannot be started, after saying why.
int runRenderHelper(int argc, char* argv[]);

}  // namespace relief::cli
