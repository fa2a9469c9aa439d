// relief: the editor. With no arguments it opens the bundled bricks sample; otherwise it opens
// the presets and maps named on the command line.
#include "DisplayCheck.h"
#include "SampleLocator.h"
#include "renderer/OpenGLProbe.h"
#include "ui/document/DocumentFiles.h"
#include "ui/settings/AppSettings.h"
#include "ui/window/DarkTheme.h"
#include "ui/window/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QCommandLineParser>
#include <QIcon>
#include <QMessageBox>
#include <QScreen>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>
#include <optional>

namespace {

using namespace relief;

// The editor's start-up options, parsed before the window exists.
struct StartOptions {
  QStringList files;
  QString screenshot;  // save a picture of the window, then quit
  bool compare = false;
  QString view;
};

StartOptions parseStartOptions(const QApplication& application) {
  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "Relief material editor. Opens the bundled bricks sample when started without files."));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addOptions({
      {QStringLiteral("screenshot"),
       QStringLiteral("Save a picture of the window to <file> once it has drawn, then quit."),
       QStringLiteral("file")},
      {QStringLiteral("compare"), QStringLiteral("Start with the A|B split comparison on.")},
      {QStringLiteral("view"), QStringLiteral("Start with a debug view (as relief-cli --view)."),
       QStringLiteral("name")},
  });
  parser.addPositionalArgument(QStringLiteral("files"),
                               QStringLiteral("Presets (.relief) or maps (images) to open."),
                               QStringLiteral("[files...]"));
  parser.process(application);
  return {parser.positionalArguments(), parser.value(QStringLiteral("screenshot")),
          parser.isSet(QStringLiteral("compare")), parser.value(QStringLiteral("view"))};
}

// Opens the files (or the sample), then the comparison, view and screenshot asked for. Returns
// an exit code when an option is wrong.
std::optional<int> startWindow(ui::MainWindow& window, StartOptions options) {
  window.setBundledPresetFolder(app::samplesDirectory());
  window.show();
  if (options.files.isEmpty() && ui::settings::openSampleOnStart()) {
    const QString sample = app::defaultSamplePreset();
    if (!sample.isEmpty())
      options.files << sample;
  }
  window.openFiles(options.files);
  // After a crash: offer the autosaved work (once the window is up, so the prompt has a parent).
  if (options.screenshot.isEmpty())
    QTimer::singleShot(0, &window, [&window] { window.files()->offerRecovery(); });
  if (options.compare)
    window.compareAction()->setChecked(true);
  if (!options.view.isEmpty()) {
    const int index = window.debugViewBox()->findData(options.view);
    if (index < 0) {
      std::fprintf(stderr, "relief: --view %s: unknown view\n",
                   options.view.toLocal8Bit().constData());
      return 2;
    }
    window.debugViewBox()->setCurrentIndex(index);
    Q_EMIT window.debugViewBox()->activated(index);
  }
  if (!options.screenshot.isEmpty()) {
    QTimer::singleShot(1500, &window, [&window, path = options.screenshot] {
      // From the screen, so overlays painted over the GL frame are in the picture too.
      const bool saved = window.screen()->grabWindow(window.winId()).save(path);
      std::fprintf(saved ? stdout : stderr, "relief: %s %s\n", saved ? "saved" : "cannot save",
                   path.toLocal8Bit().constData());
      QApplication::exit(saved ? 0 : 1);
    });
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char* argv[]) {
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
  // The desktop entry's name (packaging/), so desktops match windows to it; the icon from the
  // resources, so windows have it whether or not Relief is installed.
  QGuiApplication::setDesktopFileName(QStringLiteral("org.reliefeditor.Relief"));
  QIcon icon;
  for (int size : {16, 32, 48, 64, 128, 256})
    icon.addFile(QStringLiteral(":/icons/%1x%1/apps/org.reliefeditor.Relief.png").arg(size));
  QApplication::setWindowIcon(icon);
  ui::applyDarkTheme(application);
  const StartOptions options = parseStartOptions(application);

  // Qt crashes when a QOpenGLWidget gets no context; find out first and say so.
  if (core::Result<std::string> probe = renderer::probeOpenGL(); !probe) {
    std::fprintf(stderr, "relief: %s\n", probe.error().c_str());
    QMessageBox::critical(nullptr, QStringLiteral("Relief cannot start"),
                          QString::fromStdString(probe.error()));
    return 1;
  }
  ui::MainWindow window;
  if (auto exit = startWindow(window, options))
    return *exit;
  return application.exec();
}
