// OpenGLProbe; see OpenGLProbe.h.
#include "renderer/OpenGLProbe.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#include <link.h>

#include <cstring>
#endif

namespace relief::renderer {
namespace {

#if defined(__SANITIZE_ADDRESS__)
// LeakSanitizer names the modules in a leak's stack when it reports, at exit, after Mesa has
// dlclose'd its DRI driver; the driver's frames then belong to no module and
// tools/sanitizers/lsan.supp cannot match the driver's own leaks. Marking the loaded driver
// modules RTLD_NODELETE keeps them mapped until the report. Sanitizer builds only.
void keepDriverModulesForLeakReports() {
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) -> int {
        const char* name = info->dlpi_name;
        if (name && (std::strstr(name, "_dri.so") || std::strstr(name, "libgallium"))) {
          dlopen(name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        }
        return 0;
      },
      nullptr);
}
#else
void keepDriverModulesForLeakReports() {}
#endif

}  // namespace

QSurfaceFormat requiredSurfaceFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(4, 1);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  format.setSwapInterval(1);
  return format;
}

core::Result<std::string> probeOpenGL() {
  QOpenGLContext context;
  context.setFormat(requiredSurfaceFormat());
  if (!context.create()) {
    return core::makeError(
        "no OpenGL context could be created; Relief needs OpenGL 4.1 (core profile) and a "
        "display (on a headless machine run it under xvfb-run)");
  }
  const QSurfaceFormat actual = context.format();
  if (actual.version() < qMakePair(4, 1) || actual.profile() != QSurfaceFormat::CoreProfile) {
    return core::makeError("the OpenGL driver offers version " +
                           std::to_string(actual.majorVersion()) + "." +
                           std::to_string(actual.minorVersion()) +
                           " but Relief needs OpenGL 4.1 core profile; update the graphics "
                           "driver");
  }
  QOffscreenSurface surface;
  surface.setFormat(actual);
  surface.create();
  if (!context.makeCurrent(&surface)) {
    return core::makeError("an OpenGL 4.1 context was created but cannot be made current");
  }
  keepDriverModulesForLeakReports();
  QOpenGLFunctions* gl = context.functions();
  const auto* renderer = reinterpret_cast<const char*>(gl->glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(gl->glGetString(GL_VERSION));
  std::string description = std::string(renderer ? renderer : "unknown renderer") + ", OpenGL " +
                            (version ? version : "unknown");
  context.doneCurrent();
  return description;
}

}  // namespace relief::renderer
