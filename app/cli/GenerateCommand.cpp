// GenerateCommand; see GenerateCommand.h.
#include "GenerateCommand.h"

#include "CliCommon.h"
#include "core/generators/Generators.h"
#include "core/image/ImageIO.h"

#include <QFileInfo>

namespace relief::cli {
namespace {

QString qstr(std::string_view text) {
  return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

QString generatorList() {
  QString text;
  for (const core::GeneratorInfo& info : core::allGenerators()) {
    text += QStringLiteral("  %1%2\n").arg(qstr(info.name), -20).arg(qstr(info.description));
  }
  return text;
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
  parser.setApplicationDescription(qstr(info.label) + QStringLiteral(": ") +
                                   qstr(info.description));
  for (const core::GeneratorInput& input : info.inputs) {
    parser.addOption(QCommandLineOption(qstr(input.name), qstr(input.label) + QLatin1Char('.'),
                                        QStringLiteral("file")));
  }
  parser.addOption(QCommandLineOption(
      QStringLiteral("out"),
      QStringLiteral("Output: .png/.tif are written 16-bit, .exr float, .jpg/.tga 8-bit with "
                     "dither."),
      QStringLiteral("file")));
  for (const core::OptionSpec& option : info.options) {
    parser.addOption(QCommandLineOption(qstr(option.name),
                                        QString::fromStdString(core::describeOption(option)),
                                        QStringLiteral("value")));
  }
  if (*kind == core::GeneratorKind::Pack) {
    parser.addOption(QCommandLineOption(
        QStringLiteral("swizzle"),
        QStringLiteral("Any channel layout instead: one term per output channel, n. for the "
                       "normal map, h. for the height map, then r, g, b or a; or 0 or 1 (e.g. "
                       "\"n.r n.g n.b h.r\"). Auto-levels still apply to the height."),
        QStringLiteral("terms")));
  }
  // parseOrExit drops argv[1] ("generate"); drop the generator's name too.
  QStringList withoutGenerator = arguments;
  withoutGenerator.removeAt(2);
  const QString usage = QStringLiteral("relief-cli generate %1 ").arg(qstr(info.name)) +
                        (*kind == core::GeneratorKind::Pack
                             ? QStringLiteral("--normal N --height H --out NH [options]")
                             : QStringLiteral("--in FILE --out FILE [options]"));
  if (auto exit = parseOrExit(parser, withoutGenerator, usage))
    return *exit;
  if (!parser.positionalArguments().isEmpty()) {
    printError(QStringLiteral("generate %1: unexpected argument '%2' (see --help)")
                   .arg(qstr(info.name), parser.positionalArguments().front()));
    return kExitUsage;
  }

  core::GeneratorValues values = core::defaultGeneratorValues(*kind);
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
  if (!parser.isSet(QStringLiteral("out"))) {
    printError(QStringLiteral("generate %1 needs --out FILE").arg(qstr(info.name)));
    return kExitUsage;
  }
  std::vector<core::Image> images;
  images.reserve(info.inputs.size());
  for (const core::GeneratorInput& input : info.inputs) {
    if (!parser.isSet(qstr(input.name))) {
      printError(QStringLiteral("generate %1 needs --%2 FILE (the %3)")
                     .arg(qstr(info.name), qstr(input.name), qstr(input.label).toLower()));
      return kExitUsage;
    }
    const QString path = parser.value(qstr(input.name));
    core::Result<core::Image> image = core::loadImage(path.toStdString());
    if (!image) {
      printError(QString::fromStdString(image.error()));
      return kExitFailure;
    }
    const bool normalInput = input.defaultSlot == core::MapSlot::Normal ||
                             (*kind == core::GeneratorKind::Curvature &&
                              values[std::size_t(core::findGeneratorOption(*kind, "from"))] == 1.0);
    if (normalInput) {
      if (const auto warning = core::normalMapWarning(image.value())) {
        printError(QStringLiteral("warning: ") + path + QStringLiteral(": ") +
                   QString::fromStdString(*warning));
      }
    }
    images.push_back(std::move(image).value());
  }
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
    // The levelled height (alpha of the packed result) stands in for the height input.
    core::Image height(output.width(), output.height(), 1);
    for (std::size_t p = 0; p < height.pixelCount(); ++p)
      height.data()[p] = output.data()[p * 4 + 3];
    core::Result<core::Image> swizzled = core::swizzleChannels(
        {inputs[0], &height}, "nh", parser.value(QStringLiteral("swizzle")).toStdString());
    if (!swizzled) {
      printError(QStringLiteral("--") + QString::fromStdString(swizzled.error()));
      return kExitUsage;
    }
    output = std::move(swizzled).value();
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
