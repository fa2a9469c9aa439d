// CliCommands; see CliCommands.h.
#include "CliCommands.h"

#include "CompressCommand.h"
#include "ExportCommand.h"
#include "GenerateCommand.h"
#include "InfoCommand.h"
#include "PresetCommand.h"

#include <array>

namespace relief::cli {
namespace {

int runBatchCommand(const QStringList& arguments) {
  return runBatch(arguments, nullptr);
}

const std::array kCommands = {
    CliCommand{"render", "Render a preset or maps offscreen to an image (needs an X display)",
               nullptr},
    CliCommand{"generate",
               "Make maps from other maps: normal, height, height-from-color, ao, curvature, pack, "
               "delight; make a photo and its maps tileable",
               runGenerate},
    CliCommand{"info", "Print an image's size, channels, bit depth and colour space", runInfo},
    CliCommand{"preset", "validate FILE: check a .relief preset; info FILE: print what it holds",
               runPreset},
    CliCommand{"export",
               "Export a preset as a package, glTF 2.0, or a Godot, Unreal or Unity material",
               runExport},
    CliCommand{"compress",
               "Compress a map into BC1-BC7, DXT5nm, ETC1/ETC2, EAC or ASTC (DDS, KTX2)",
               runCompress},
    CliCommand{"decode", "Decode a DDS or KTX2 file to an image", runDecode},
    CliCommand{"compare",
               "Print quality metrics between a reference and a candidate image or texture",
               runCompare},
    CliCommand{"batch", "Run many jobs (one command line each in a file) in one process",
               runBatchCommand},
};

}  // namespace

std::span<const CliCommand> cliCommands() {
  return kCommands;
}

const CliCommand* findCliCommand(const QString& name) {
  for (const CliCommand& command : kCommands) {
    if (name == QLatin1String(command.name))
      return &command;
  }
  return nullptr;
}

}  // namespace relief::cli
