// GenerateCommand; see GenerateCommand.h.
#include "GenerateCommand.h"

#include "CliCommon.h"
#include "core/compression/MapFile.h"
#include "core/generators/Generators.h"
#include "core/image/ImageIO.h"

#include <QFileInfo>

namespace relief::cli {
namespace {

QString generatorList() {
  QString text;
  for (const core::GeneratorInfo& info : core::allGenerators()) {
    text += QStringLiteral("  %1%2\n").arg(qstr(info.name), -20).arg(qstr(info.description));
  }
  return text;
}

// The generator's options: its inputs, --out, its OptionSpecs (core's table) and pack's swizzle.
CliOptions generatorOptions(const core::GeneratorInfo& info) {
  CliOptions options;
  for (const core::GeneratorInput& input : info.inputs)
    options.push_back(
        {qstr(input.name), QStringLiteral("file"), qstr(input.label) + QLatin1Char('.'), {}});
  options.push_back(
      {QStringLiteral("out"),
       QStringLiteral("file"),
       QStringLiteral("Output: .png/.tif are written 16-bit, .exr float, .jpg/.tga 8-bit with "
                      "dither."),
       {}});
  for (const core::OptionSpec& option : info.options) {
    options.push_back({qstr(option.name),
                       QStringLiteral("value"),
                       QString::fromStdString(core::describeOption(option)),
                       {}});
  }
  if (info.kind == core::GeneratorKind::Pack) {
    options.push_back(
        {QStringLiteral("swizzle"),
         QStringLiteral("terms"),
         QStringLiteral("Any channel layout instead: one term per output channel, n. for the "
                        "normal map, h. for the height map, then r, g, b or a; or 0 or 1 (e.g. "
                        "\"n.r n.g n.b h.r\"). Auto-levels still apply to the height."),
         {}});
  }
  return options;
}

// The option values (defaults where not given); an exit code for a bad value.
std::optional<int> parseValues(const QCommandLineParser& parser, const core::GeneratorInfo& info,
                               core::GeneratorValues& values) {
  values = core::defaultGeneratorValues(info.kind);
  for (std::size_t i = 0; i < info.options.size(); ++i) {
    const QString name = qstr(info.options[i].name);
    if (!parser.isSet(name))
      continue;
    core::Result<double> value =
        core::parseOptionValue(info.options[i], parser.value(name).toStdString());
    if (!value) {
      printError(QStringLiteral("--") + QString::fromStdString(value.error()));
      return kExitUsage;
    }
    values[i] = value.value();
  }
  return std::nullopt;
}

// The input maps, in the order of the generator's inputs; warns when a normal input does not
// look like a normal map.
std::optional<int> loadInputs(const QCommandLineParser& parser, const core::GeneratorInfo& info,
                              const core::GeneratorValues& values,
                              std::vector<core::Image>& images) {
  for (const core::GeneratorInput& input : info.inputs) {
    if (!parser.isSet(qstr(input.name))) {
      printError(QStringLiteral("generate %1 needs --%2 FILE (the %3)")
                     .arg(qstr(info.name), qstr(input.name), qstr(input.label).toLower()));
      return kExitUsage;
    }
    const QString path = parser.value(qstr(input.name));
    core::Result<core::Image> image = core::loadMapFile(path.toStdString());
    if (!image) {
      printError(QString::fromStdString(image.error()));
      return kExitFailure;
    }
    const bool normalInput =
        input.defaultSlot == core::MapSlot::Normal ||
        (info.kind == core::GeneratorKind::Curvature &&
         values[std::size_t(core::findGeneratorOption(info.kind, "from"))] == 1.0);
    if (normalInput) {
      if (const auto warning = core::normalMapWarning(image.value())) {
        printError(QStringLiteral("warning: ") + path + QStringLiteral(": ") +
                   QString::fromStdString(*warning));
      }
    }
    images.push_back(std::move(image).value());
  }
  return std::nullopt;
}

// pack --swizzle: the channels laid out as asked, the levelled height (the packed result's
// alpha) standing in for the height input.
std::optional<int> swizzle(const QString& terms, const core::Image& normal, core::Image& output) {
  core::Image height(output.width(), output.height(), 1);
  for (std::size_t p = 0; p < height.pixelCount(); ++p)
    height.data()[p] = output.data()[p * 4 + 3];
  core::Result<core::Image> swizzled =
      core::swizzleChannels({&normal, &height}, "nh", terms.toStdString());
  if (!swizzled) {
    printError(QStringLiteral("--") + QString::fromStdString(swizzled.error()));
    return kExitUsage;
  }
  output = std::move(swizzled).value();
  return std::nullopt;
}

// Parses the generator's own command line (argv[2] is its name).
std::optional<int> parseGenerator(QCommandLineParser& parser, const core::GeneratorInfo& info,
                                  const QStringList& arguments) {
  parser.setApplicationDescription(qstr(info.label) + QStringLiteral(": ") +
                                   qstr(info.description));
  addOptions(parser, generatorOptions(info));
  // parseOrExit drops argv[1] ("generate"); drop the generator's name too.
  QStringList withoutGenerator = arguments;
  withoutGenerator.removeAt(2);
  const QString usage = QStringLiteral("relief-cli generate %1 ").arg(qstr(info.name)) +
                        (info.kind == core::GeneratorKind::Pack
                             ? QStringLiteral("--normal N --height H --out NH [options]")
                             : QStringLiteral("--in FILE --out FILE [options]"));
  if (auto exit = parseOrExit(parser, withoutGenerator, usage))
    return exit;
  if (!parser.positionalArguments().isEmpty()) {
    printError(QStringLiteral("generate %1: unexpected argument '%2' (see --help)")
                   .arg(qstr(info.name), parser.positionalArguments().front()));
    return kExitUsage;
  }
  if (!parser.isSet(QStringLiteral("out"))) {
    printError(QStringLiteral("generate %1 needs --out FILE").arg(qstr(info.name)));
    return kExitUsage;
  }
  return std::nullopt;
}

}  // namespace

int runGenerate(const QStringList& arguments) {
  const QString usageTop = QStringLiteral(
                               "Usage: relief-cli generate <generator> [options]\n\n"
                               "Generators:\n") +
                           generatorList() +
                           QStringLiteral(
                               "\nRun 'relief-cli generate <generator> --help' for its "
                               "options.\n");
  if (arguments.size() < 3 || arguments[2] == QStringLiteral("--help") ||
      arguments[2] == QStringLiteral("-h")) {
    printOut(usageTop);
    return arguments.size() < 3 ? kExitUsage : kExitOk;
  }
  const std::optional<core::GeneratorKind> kind = core::findGenerator(arguments[2].toStdString());
  if (!kind) {
    printError(QStringLiteral("generate: unknown generator '%1'").arg(arguments[2]));
    printOut(usageTop);
    return kExitUsage;
  }
  const core::GeneratorInfo& info = core::generatorInfo(*kind);
  QCommandLineParser parser;
  if (auto exit = parseGenerator(parser, info, arguments))
    return *exit;
  core::GeneratorValues values;
  std::vector<core::Image> images;
  if (auto exit = parseValues(parser, info, values))
    return *exit;
  if (auto exit = loadInputs(parser, info, values, images))
    return *exit;
  std::vector<const core::Image*> inputs;
  for (const core::Image& image : images)
    inputs.push_back(&image);

  core::Result<core::GeneratedMap> result = core::runGenerator({*kind, inputs, values, 1.0});
  if (!result) {
    printError(QStringLiteral("generate %1: ").arg(qstr(info.name)) +
               QString::fromStdString(result.error()));
    return kExitFailure;
  }
  core::Image output = std::move(result->image);
  if (*kind == core::GeneratorKind::Pack && parser.isSet(QStringLiteral("swizzle"))) {
    if (auto exit = swizzle(parser.value(QStringLiteral("swizzle")), images.front(), output))
      return *exit;
  }
  const QString outPath = parser.value(QStringLiteral("out"));
  if (core::Status saved = core::saveImage(output, outPath.toStdString(),
                                           core::fullPrecisionFormatFor(outPath.toStdString()));
      !saved) {
    printError(QString::fromStdString(saved.error()));
    return kExitFailure;
  }
  for (const std::string& note : result->notes) {
    printOut(QString::fromStdString(note) + QLatin1Char('\n'));
  }
  return kExitOk;
}

}  // namespace relief::cli
