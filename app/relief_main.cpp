// relief: the editor. With no arguments it opens the bundled bricks sample; otherwise it opens
// the presets and maps named on the command line.
#include "DisplayCheck.h"
#include "SampleLocator.h"
#include "renderer/OpenGLProbe.h"
#include "ui/DarkTheme.h"
#include "ui/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QMessageBox>
#include <QSurfaceFormat>

#include <cstdio>

int main(int argc, char* argv[]) {
  using namespace relief;
  if (const std::string problem = app::displayProblem(); !problem.empty()) {
    std::fprintf(stderr, "relief: %s\n", problem.c_str());
    return 1;
  }
  // Every context (viewport, offscreen) shares this format; set before the application exists.
  QSurfaceFormat::setDefaultFormat(renderer::requiredSurfaceFormat());
  QApplication application(argc, argv);
  QApplication::setApplicationName(QStringLiteral("Relief"));
  QApplication::setOrganizationName(QStringLiteral("Relief"));
  QApplication::setApplicationVersion(QStringLiteral(RELIEF_VERSION));
  ui::applyDarkTheme(application);

  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "Relief material editor. Opens the bundled bricks sample when started without files."));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(QStringLiteral("files"),
                               QStringLiteral("Presets (.relief) or maps (images) to open."),
                               QStringLiteral("[files...]"));
  parser.process(application);

  // Qt crashes when a QOpenGLWidget gets no context; find out first and say so.
  if (core::Result<std::string> probe = renderer::probeOpenGL(); !probe) {
    std::fprintf(stderr, "relief: %s\n", probe.error().c_str());
    QMessageBox::critical(nullptr, QStringLiteral("Relief cannot start"),
                          QString::fromStdString(probe.error()));
    return 1;
  }

  ui::MainWindow window;
  window.show();
  QStringList files = parser.positionalArguments();
  if (files.isEmpty()) {
    const QString sample = app::defaultSamplePreset();
    if (!sample.isEmpty())
      files << sample;
  }
  window.openFiles(files);
  return application.exec();
}
