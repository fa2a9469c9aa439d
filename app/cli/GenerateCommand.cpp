// GenerateCommand; see GenerateCommand.h.
#include "GenerateCommand.h"

#include "app/cli/CliOptionNames.h"

#include "CliCommon.h"
#include "TerminalProgress.h"
#include "TileableCommand.h"
#include "core/compression/MapFile.h"
#include "core/generators/Generators.h"
#include "core/image/ImageIO.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>
#include <iterator>

namespace relief::cli {
namespace {

QString generatorList() {
  QString text;
  for (const core::GeneratorInfo& info : core::allGenerators()) {
    text += QStringLiteral("  %1%2\n").arg(qstr(info.name), -20).arg(qstr(info.description));
  }
  text += QStringLiteral("  %1%2\n")
              .arg(QStringLiteral("tileable"), -20)
              .arg(QStringLiteral("A photo and the maps aligned with it made to tile "
                                  "(--out-dir; see its --help)"));
  return text;
}

// pack's extras on the command line: a map that only the channel terms use (color), and the
// channel terms; pack's own inputs come from core's table.
constexpr const char* kPackExtraMaps[] = {"color"};
constexpr const char* kChannelOptions[] = {"r", "g", "b", "a"};

// The generator's options: its inputs, --out, its OptionSpecs (core's table) and pack's swizzle.
CliOptions generatorOptions(const core::GeneratorInfo& info) {
  CliOptions options;
  for (const core::GeneratorInput& input : info.inputs)
    options.push_back(
        {qstr(input.name), QStringLiteral("file"), qstr(input.label) + QLatin1Char('.'), {}});
  options.push_back(
      {option::kOut,
       QStringLiteral("file"),
       QStringLiteral("Output: .png/.tif are written 16-bit, .exr float, .jpg/.tga 8-bit with "
                      "dither."),
       {}});
  options.push_back(jsonOption());
  for (const core::OptionSpec& option : info.options) {
    options.push_back({qstr(option.name),
                       QStringLiteral("value"),
                       QString::fromStdString(core::describeOption(option)),
                       {}});
  }
  if (info.kind == core::GeneratorKind::Pack) {
    for (const char* map : kPackExtraMaps) {
      options.push_back({QLatin1String(map),
                         QStringLiteral("file"),
                         QStringLiteral("The %1 map, for --layout and the channel terms.")
                             .arg(QLatin1String(map)),
                         {}});
    }
    for (const char* channel : kChannelOptions) {
      options.push_back(
          {QLatin1String(channel),
           QStringLiteral("term"),
           QStringLiteral("Output channel %1: MAP.c (a map option's name and its channel r, g, "
                          "b or a, e.g. ao.r), 1-MAP.c (inverted, e.g. 1-roughness.r for "
                          "smoothness) or a constant in 0..1. Overrides --layout's.")
               .arg(QString::fromLatin1(channel).toUpper()),
           {}});
    }
    options.push_back(
        {option::kSwizzle,
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
    if (!parser.isSet(qstr(input.name)) && input.optional) {
      images.emplace_back();  // an empty image: not given
      continue;
    }
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

// What a generator made: its notes as lines, or with --json one object with the output's path,
// size, channels, notes and (height from normal, pack) the depth or height range.
void reportGenerated(const QCommandLineParser& parser, std::string_view generator,
                     const QString& outPath, const core::Image& image,
                     const std::vector<std::string>& notes,
                     const std::optional<core::LevelsRange>& levels = std::nullopt,
                     const std::optional<double>& depthTexels = std::nullopt) {
  if (!parser.isSet(option::kJson)) {
    for (const std::string& note : notes)
      printNote(QString::fromStdString(note) + QLatin1Char('\n'));
    return;
  }
  QJsonArray noteArray;
  for (const std::string& note : notes)
    noteArray.append(QString::fromStdString(note));
  QJsonObject object{
      {QStringLiteral("generator"), qstr(generator)}, {QStringLiteral("output"), outPath},
      {QStringLiteral("width"), image.width()},       {QStringLiteral("height"), image.height()},
      {QStringLiteral("channels"), image.channels()}, {QStringLiteral("notes"), noteArray}};
  if (levels) {
    object.insert(
        QStringLiteral("heightRange"),
        QJsonObject{{QStringLiteral("low"), levels->low}, {QStringLiteral("high"), levels->high}});
  }
  if (depthTexels)
    object.insert(QStringLiteral("depthTexels"), *depthTexels);
  printJson(object);
}

// pack with channel terms or maps only the terms can name (--color): any map or
// constant into any channel, starting from --layout's terms. Returns nullopt when none of those
// is given (core's pack generator runs, with --layout and the table's inputs).
std::optional<int> runChannelPack(const QCommandLineParser& parser,
                                  const core::GeneratorInfo& info) {
  const auto given = [&](const char* option) { return parser.isSet(QLatin1String(option)); };
  if (std::none_of(std::begin(kChannelOptions), std::end(kChannelOptions), given) &&
      std::none_of(std::begin(kPackExtraMaps), std::end(kPackExtraMaps), given))
    return std::nullopt;
  QStringList mapOptions;
  for (const core::GeneratorInput& input : info.inputs)
    mapOptions << qstr(input.name);
  for (const char* map : kPackExtraMaps)
    mapOptions << QLatin1String(map);
  std::vector<core::Image> images;
  std::vector<std::string> names;
  for (const QString& option : mapOptions) {
    if (!parser.isSet(option))
      continue;
    const QString path = parser.value(option);
    core::Result<core::Image> image = core::loadMapFile(path.toStdString());
    if (!image) {
      printError(QString::fromStdString(image.error()));
      return kExitFailure;
    }
    images.push_back(std::move(image).value());
    names.push_back(option.toStdString());
  }
  std::vector<core::NamedMap> maps;
  for (std::size_t i = 0; i < images.size(); ++i)
    maps.push_back({names[i], &images[i]});
  std::vector<std::string> terms;
  std::vector<std::string> substituted;
  if (parser.isSet(option::kLayout)) {
    const core::PackLayout* layout =
        core::findPackLayout(parser.value(option::kLayout).toStdString());
    if (!layout) {
      QStringList known;
      for (const core::PackLayout& entry : core::packLayouts())
        known << qstr(entry.name);
      printError(QStringLiteral("--layout %1: expected %2")
                     .arg(parser.value(option::kLayout), known.join(QLatin1Char('|'))));
      return kExitUsage;
    }
    terms = core::resolveLayoutTerms(*layout, maps, &substituted);
  }
  for (std::size_t c = 0; c < std::size(kChannelOptions); ++c) {
    const QString option = QLatin1String(kChannelOptions[c]);
    if (!parser.isSet(option))
      continue;
    if (terms.size() < c) {
      printError(QStringLiteral("--%1 given without the channels before it").arg(option));
      return kExitUsage;
    }
    if (terms.size() == c)
      terms.push_back({});
    terms[c] = parser.value(option).toStdString();
  }
  core::Result<core::Image> packed = core::packChannels(maps, terms);
  if (!packed) {
    printError(QStringLiteral("generate pack: ") + QString::fromStdString(packed.error()));
    return kExitUsage;
  }
  const QString outPath = parser.value(option::kOut);
  if (core::Status saved = core::saveImage(packed.value(), outPath.toStdString(),
                                           core::fullPrecisionFormatFor(outPath.toStdString()));
      !saved) {
    printError(QString::fromStdString(saved.error()));
    return kExitFailure;
  }
  std::vector<std::string> notes;
  for (const std::string& name : substituted)
    notes.push_back(core::neutralValueNote(name));
  reportGenerated(parser, "pack", outPath, packed.value(), notes);
  return kExitOk;
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
                             ? QStringLiteral("[--layout NAME] [--normal F --height F --ao F "
                                              "--roughness F --metallic F --color F] [--r TERM "
                                              "...] --out FILE")
                             : QStringLiteral("--in FILE --out FILE [options]"));
  if (auto exit = parseOrExit(parser, withoutGenerator, usage))
    return exit;
  if (!parser.positionalArguments().isEmpty()) {
    printError(QStringLiteral("generate %1: unexpected argument '%2' (see --help)")
                   .arg(qstr(info.name), parser.positionalArguments().front()));
    return kExitUsage;
  }
  if (!parser.isSet(option::kOut)) {
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
  if (arguments[2] == QStringLiteral("tileable"))
    return runTileable(arguments);  // many maps in, many out: not one of the table's generators
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
  if (*kind == core::GeneratorKind::Pack) {
    if (auto exit = runChannelPack(parser, info))
      return *exit;
  }
  core::GeneratorValues values;
  std::vector<core::Image> images;
  if (auto exit = parseValues(parser, info, values))
    return *exit;
  if (auto exit = loadInputs(parser, info, values, images))
    return *exit;
  std::vector<const core::Image*> inputs;
  for (const core::Image& image : images)
    inputs.push_back(image.isEmpty() ? nullptr : &image);

  core::Result<core::GeneratedMap> result = [&] {
    TerminalProgress progress(QStringLiteral("generate ") + qstr(info.name));
    return core::runGenerator({*kind, inputs, values, 1.0}, progress.control());
  }();
  if (!result) {
    printError(QStringLiteral("generate %1: ").arg(qstr(info.name)) +
               QString::fromStdString(result.error()));
    return kExitFailure;
  }
  core::Image output = std::move(result->image);
  if (*kind == core::GeneratorKind::Pack && parser.isSet(option::kSwizzle)) {
    if (images.front().isEmpty() || output.channels() != 4) {
      printError(
          QStringLiteral("--swizzle rearranges the normal-height layout: give --normal and "
                         "--height (or use --r, --g, --b, --a for other layouts)"));
      return kExitUsage;
    }
    if (auto exit = swizzle(parser.value(option::kSwizzle), images.front(), output))
      return *exit;
  }
  const QString outPath = parser.value(option::kOut);
  if (core::Status saved = core::saveImage(output, outPath.toStdString(),
                                           core::fullPrecisionFormatFor(outPath.toStdString()));
      !saved) {
    printError(QString::fromStdString(saved.error()));
    return kExitFailure;
  }
  reportGenerated(parser, info.name, outPath, output, result->notes, result->levels,
                  result->depthTexels);
  return kExitOk;
}

}  // namespace relief::cli
