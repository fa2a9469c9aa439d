// relief: the editor. With no arguments it opens the bundled bricks sample; otherwise it opens
// the presets and maps named on the command line.
#include "DisplayCheck.h"
#include "SampleLocator.h"
#include "renderer/OpenGLProbe.h"
#include "ui/document/DocumentFiles.h"
#include "ui/window/AppSettings.h"
#include "ui/window/DarkTheme.h"
#include "ui/window/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QCommandLineParser>
#include <QMessageBox>
#include <QScreen>
#include <QSurfaceFormat>
#include <QTimer>

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
  const QCommandLineOption screenshot(
      QStringLiteral("screenshot"),
      QStringLiteral("Save a picture of the window to <file> once it has drawn, then quit."),
      QStringLiteral("file"));
  parser.addOption(screenshot);
  const QCommandLineOption compare(QStringLiteral("compare"),
                                   QStringLiteral("Start with the A|B split comparison on."));
  parser.addOption(compare);
  const QCommandLineOption view(QStringLiteral("view"),
                                QStringLiteral("Start with a debug view (as relief-cli --view)."),
                                QStringLiteral("name"));
  parser.addOption(view);
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
  window.setBundledPresetFolder(app::samplesDirectory());
  window.show();
  QStringList files = parser.positionalArguments();
  if (files.isEmpty() && ui::settings::openSampleOnStart()) {
    const QString sample = app::defaultSamplePreset();
    if (!sample.isEmpty())
      files << sample;
  }
  window.openFiles(files);
  // After a crash: offer the autosaved work (once the window is up, so the prompt has a parent).
  if (!parser.isSet(screenshot))
    QTimer::singleShot(0, &window, [&window] { window.files()->offerRecovery(); });
  if (parser.isSet(compare))
    window.compareAction()->setChecked(true);
  if (parser.isSet(view)) {
    const int index = window.debugViewBox()->findData(parser.value(view));
    if (index < 0) {
      std::fprintf(stderr, "relief: --view %s: unknown view\n",
                   parser.value(view).toLocal8Bit().constData());
      return 2;
    }
    window.debugViewBox()->setCurrentIndex(index);
    Q_EMIT window.debugViewBox()->activated(index);
  }
  if (parser.isSet(screenshot)) {
    const QString path = parser.value(screenshot);
    QTimer::singleShot(1500, &window, [&window, path] {
      // From the screen, so overlays painted over the GL frame are in the picture too.
      const bool saved = window.screen()->grabWindow(window.winId()).save(path);
      std::fprintf(saved ? stdout : stderr, "relief: %s %s\n", saved ? "saved" : "cannot save",
                   path.toLocal8Bit().constData());
      QApplication::exit(saved ? 0 : 1);
    });
  }
  return application.exec();
}
