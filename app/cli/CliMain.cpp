// relief-cli: Relief's command-line twin. The commands are one table (CliCommands.h) that
// dispatch, the usage text and `relief-cli help` read; each command's options are a table in its
// own file.
#include "CliCommands.h"
#include "CliCommon.h"
#include "RenderHelper.h"
#include "SampleLocator.h"

#include "core/base/TemporaryFiles.h"

#include <QCoreApplication>

#include <cstring>

namespace {

using namespace relief::cli;

QString usage() {
  QString text = QStringLiteral("Usage: relief-cli <command> [options]\n\nCommands:\n");
  for (const CliCommand& command : cliCommands()) {
    text += QStringLiteral("  %1 %2\n")
                .arg(QString::fromLatin1(command.name), -8)
                .arg(QString::fromUtf8(command.summary));
  }
  return text + QStringLiteral(
                    "\nRun 'relief-cli <command> --help' for a command's options, "
                    "'relief-cli --version' for the version and the samples' folder.\n"
                    "Any command takes --quiet (-q): no informational lines, only results, "
                    "warnings and errors.\nLong commands draw a progress line when standard "
                    "error is a terminal.\nExit codes: 0 success, 1 the work failed (the "
                    "message names the file), 2 a wrong command line.\n");
}

}  // namespace

int main(int argc, char* argv[]) {
  takeQuietFlag(argc, argv);
  // Ctrl+C or a farm's SIGTERM during a save leaves neither the target half-written nor its
  // temporary behind.
  relief::core::removeTemporaryFilesOnSignal();
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0 ||
      std::strcmp(argv[1], "help") == 0) {
    printOut(usage());
    return argc < 2 ? kExitUsage : kExitOk;
  }
  if (std::strcmp(argv[1], "--version") == 0) {
    // The version, and where the bundled samples were found (an install's share/relief/samples
    // or the source tree of a build), which says which installation is running.
    QCoreApplication application(argc, argv);
    const QString samples = relief::app::samplesDirectory();
    printOut(QStringLiteral("relief-cli %1\nsamples: %2\n")
                 .arg(QStringLiteral(RELIEF_VERSION),
                      samples.isEmpty() ? QStringLiteral("not found") : samples));
    return kExitOk;
  }
  const CliCommand* command = findCliCommand(QString::fromLocal8Bit(argv[1]));
  if (!command) {
    printError(QStringLiteral("unknown command '%1'").arg(QString::fromLocal8Bit(argv[1])));
    printOut(usage());
    return kExitUsage;
  }
  // render, compare --rendered, compress --preset and a batch with render jobs run where GL is
  // linked (RenderHelper.h).
  if (!command->run)
    return runRenderHelper(argc, argv);
  // compare --rendered and compress --preset (choose for me) render the material.
  const bool compare = std::strcmp(argv[1], "compare") == 0;
  const bool compress = std::strcmp(argv[1], "compress") == 0;
  for (int i = 2; i < argc && (compare || compress); ++i) {
    if ((compare && std::strcmp(argv[i], "--rendered") == 0) ||
        (compress &&
         (std::strcmp(argv[i], "--preset") == 0 || std::strncmp(argv[i], "--preset=", 9) == 0)))
      return runRenderHelper(argc, argv);
  }
  int exitCode = kExitOk;
  {
    QCoreApplication application(argc, argv);
    exitCode = command->run(QCoreApplication::arguments());
  }
  return exitCode == kBatchNeedsRenderer ? runRenderHelper(argc, argv) : exitCode;
}
