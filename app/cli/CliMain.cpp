// relief-cli: Relief's command-line twin. One table of commands (name, summary, entry point)
// that dispatch, the usage text and `relief-cli help` read; each command's options are a table
// in its own file.
#include "CliCommon.h"
#include "CompressCommand.h"
#include "ExportCommand.h"
#include "GenerateCommand.h"
#include "InfoCommand.h"
#include "PresetCommand.h"
#include "RenderCommand.h"
#include "SampleLocator.h"

#include <QCoreApplication>

#include <array>
#include <cstring>
#include <vector>

namespace {

using namespace relief::cli;

struct Command {
  const char* name;
  const char* summary;
  // render makes its own QGuiApplication (it needs a display); the rest run in a
  // QCoreApplication made here.
  int (*runWithArgv)(int argc, char* argv[]);
  int (*run)(const QStringList& arguments);
};

const std::array kCommands = {
    Command{"render", "Render a preset or maps offscreen to an image (needs an X display)",
            runRender, nullptr},
    Command{"generate",
            "Make maps from other maps: normal, height, height-from-color, ao, curvature, pack",
            nullptr, runGenerate},
    Command{"info", "Print an image's size, channels, bit depth and colour space", nullptr,
            runInfo},
    Command{"preset", "validate FILE: check a .relief preset; info FILE: print what it holds",
            nullptr, runPreset},
    Command{"export",
            "Export a preset as a package, glTF 2.0, or a Godot, Unreal or Unity material", nullptr,
            runExport},
    Command{"compress", "Compress a map into BC1-BC7, DXT5nm, ETC1/ETC2, EAC or ASTC (DDS, KTX2)",
            nullptr, runCompress},
    Command{"decode", "Decode a DDS or KTX2 file to an image", nullptr, runDecode},
    Command{"compare", "Print quality metrics between a reference and a candidate image or texture",
            nullptr, runCompare},
};

QString usage() {
  QString text = QStringLiteral("Usage: relief-cli <command> [options]\n\nCommands:\n");
  for (const Command& command : kCommands) {
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
  // --quiet (or -q) anywhere on the line applies to every command; it is taken out before the
  // command parses the rest.
  std::vector<char*> kept;
  for (int i = 0; i < argc; ++i) {
    if (i > 0 && (std::strcmp(argv[i], "--quiet") == 0 || std::strcmp(argv[i], "-q") == 0)) {
      setQuiet(true);
      continue;
    }
    kept.push_back(argv[i]);
  }
  argc = int(kept.size());
  kept.push_back(nullptr);
  argv = kept.data();
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
  for (const Command& command : kCommands) {
    if (std::strcmp(argv[1], command.name) != 0)
      continue;
    if (command.runWithArgv)
      return command.runWithArgv(argc, argv);
    QCoreApplication application(argc, argv);
    return command.run(QCoreApplication::arguments());
  }
  printError(QStringLiteral("unknown command '%1'").arg(QString::fromLocal8Bit(argv[1])));
  printOut(usage());
  return kExitUsage;
}
