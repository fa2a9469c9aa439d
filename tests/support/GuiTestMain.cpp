// main() for tests that need a QApplication (GL contexts, widgets): sets the surface format
// Relief uses before the application exists, then runs GoogleTest.
#include "renderer/OpenGLProbe.h"

#include <QApplication>
#include <QDir>
#include <QSurfaceFormat>

#include <gtest/gtest.h>

#include <cstdio>

int main(int argc, char* argv[]) {
  ::testing::InitGoogleTest(&argc, argv);
  // Settings, presets, recovery files and caches of this process only: tests run in parallel
  // and must neither see the user's files nor each other's.
  const QByteArray home = QDir::tempPath().toUtf8() + "/relief-gui-test-" +
                          QByteArray::number(QCoreApplication::applicationPid());
  for (const char* variable : {"XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"}) {
    qputenv(variable, home + "/" + variable);
    QDir().mkpath(QString::fromUtf8(home + "/" + variable));
  }
  QSurfaceFormat::setDefaultFormat(relief::renderer::requiredSurfaceFormat());
  QApplication application(argc, argv);
  // As relief's main() does: fail clearly when there is no usable OpenGL.
  if (relief::core::Result<std::string> probe = relief::renderer::probeOpenGL(); !probe) {
    std::fprintf(stderr, "%s\n", probe.error().c_str());
    return 1;
  }
  QApplication::setOrganizationName(QStringLiteral("Relief"));
  QApplication::setApplicationName(QStringLiteral("Relief"));
  const int result = RUN_ALL_TESTS();
  QDir(QString::fromUtf8(home)).removeRecursively();
  return result;
}
