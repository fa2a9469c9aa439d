// relief-cli: Relief's command-line twin. Dispatches to one command per verb.
#include "CliCommon.h"
#include "CompressCommand.h"
#include "ExportCommand.h"
#include "GenerateCommand.h"
#include "InfoCommand.h"
#include "PresetCommand.h"
#include "RenderCommand.h"

#include <QCoreApplication>

#include <cstring>

namespace {

const char* kUsage =
    "Usage: relief-cli <command> [options]\n"
    "\n"
    "Commands:\n"
    "  render   Render a preset or maps offscreen to an image (needs an X display)\n"
    "  generate Make maps from other maps: normal, height, height-from-color, ao,\n"
    "           curvature, pack\n"
    "  info     Print an image's size, channels, bit depth and colour space\n"
    "  preset   validate FILE: check a .relief preset; info FILE: print what it holds\n"
    "  export   Export a preset as a package, glTF 2.0 or a Godot 4 material\n"
    "  compress Compress a map into BC1-BC5, DXT5nm, ETC1/ETC2, EAC or ASTC (DDS, KTX2)\n"
    "  decode   Decode a DDS or KTX2 file to an image\n"
    "  compare  Print quality metrics between a reference and a candidate image or texture\n"
    "\n"
    "Run 'relief-cli <command> --help' for a command's options.\n";

}  // namespace

int main(int argc, char* argv[]) {
  using namespace relief::cli;
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0 ||
      std::strcmp(argv[1], "help") == 0) {
    printOut(QString::fromUtf8(kUsage));
    return argc < 2 ? kExitUsage : kExitOk;
  }
  const QString command = QString::fromLocal8Bit(argv[1]);
  if (command == QStringLiteral("render"))
    return runRender(argc, argv);

  QCoreApplication application(argc, argv);
  if (command == QStringLiteral("info"))
    return runInfo(QCoreApplication::arguments());
  if (command == QStringLiteral("generate"))
    return runGenerate(QCoreApplication::arguments());
  if (command == QStringLiteral("preset"))
    return runPreset(QCoreApplication::arguments());
  if (command == QStringLiteral("export"))
    return runExport(QCoreApplication::arguments());
  if (command == QStringLiteral("compress"))
    return runCompress(QCoreApplication::arguments());
  if (command == QStringLiteral("decode"))
    return runDecode(QCoreApplication::arguments());
  if (command == QStringLiteral("compare"))
    return runCompare(QCoreApplication::arguments());
  printError(QStringLiteral("unknown command '%1'").arg(command));
  printOut(QString::fromUtf8(kUsage));
  return kExitUsage;
}
