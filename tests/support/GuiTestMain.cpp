// main() for tests that need a QApplication (GL contexts, widgets): sets the surface format
// Relief uses before the application exists, then runs GoogleTest.
#include "renderer/OpenGLProbe.h"

#include <QApplication>
#include <QSurfaceFormat>

#include <gtest/gtest.h>

#include <cstdio>

int main(int argc, char* argv[]) {
  ::testing::InitGoogleTest(&argc, argv);
  QSurfaceFormat::setDefaultFormat(relief::renderer::requiredSurfaceFormat());
  QApplication application(argc, argv);
  // As relief's main() does: fail clearly when there is no usable OpenGL.
  if (relief::core::Result<std::string> probe = relief::renderer::probeOpenGL(); !probe) {
    std::fprintf(stderr, "%s\n", probe.error().c_str());
    return 1;
  }
  return RUN_ALL_TESTS();
}
