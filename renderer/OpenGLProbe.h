// Checks, before any window is shown, that an OpenGL 4.1 core context can be created. Qt
// crashes rather than failing cleanly when a QOpenGLWidget cannot get a context, so the GUI and
// the CLI ask here first and print a clear message instead.
#pragma once

#include "core/base/Result.h"

#include <QSurfaceFormat>

#include <string>

namespace relief::renderer {

// The context every Relief surface asks for: OpenGL 4.1 core, 24-bit depth.
QSurfaceFormat requiredSurfaceFormat();

// Needs a QGuiApplication. Returns "renderer, OpenGL version" on success.
core::Result<std::string> probeOpenGL();

}  // namespace relief::renderer
