// CliCommon; see CliCommon.h.
#include "CliCommon.h"

#include "app/cli/CliOptionNames.h"

#include "core/mesh/MeshImport.h"
#include "core/mesh/MeshPrimitives.h"

#include <QFileInfo>
#include <QJsonDocument>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace relief::cli {

void printOut(const QString& text) {
  std::fputs(text.toLocal8Bit().constData(), stdout);
  std::fflush(stdout);
}

namespace {
bool g_quiet = false;  // set once by main() before any command runs
}  // namespace

void setQuiet(bool quiet) {
  g_quiet = quiet;
}

bool quiet() {
  return g_quiet;
}

void takeQuietFlag(int& argc, char* argv[]) {
  int kept = 0;
  for (int i = 0; i < argc; ++i) {
    if (i > 0 && (std::strcmp(argv[i], "--quiet") == 0 || std::strcmp(argv[i], "-q") == 0)) {
      setQuiet(true);
      continue;
    }
    argv[kept++] = argv[i];
  }
  argc = kept;
  argv[argc] = nullptr;
}

void printNote(const QString& text) {
  if (!g_quiet)
    printOut(text);
}

namespace {
ErrorCapture* g_errorCapture = nullptr;  // the innermost; commands run on the main thread
}  // namespace

ErrorCapture::ErrorCapture() : m_outer(g_errorCapture) {
  g_errorCapture = this;
}

ErrorCapture::~ErrorCapture() {
  g_errorCapture = m_outer;
}

void printError(const QString& text) {
  std::fprintf(stderr, "relief-cli: %s\n", text.toLocal8Bit().constData());
  if (g_errorCapture)
    g_errorCapture->m_messages << text;
}

QStringList argumentsFrom(int argc, char* argv[]) {
  QStringList arguments;
  for (int i = 0; i < argc; ++i)
    arguments << QString::fromLocal8Bit(argv[i]);
  return arguments;
}

std::optional<int> parseOrExit(QCommandLineParser& parser, const QStringList& arguments,
                               const QString& usage) {
  const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                QStringLiteral("Show this help."));
  parser.addOption(help);
  // The command name is not a positional argument of the command.
  QStringList withoutCommand = arguments;
  if (withoutCommand.size() > 1)
    withoutCommand.removeAt(1);
  if (!parser.parse(withoutCommand)) {
    printError(parser.errorText() + QStringLiteral(" (see --help)"));
    return kExitUsage;
  }
  if (parser.isSet(help)) {
    QString text = parser.helpText();
    // QCommandLineParser's first line names the binary only; show the command's real usage.
    const qsizetype firstNewline = text.indexOf(QLatin1Char('\n'));
    text = QStringLiteral("Usage: ") + usage + text.mid(firstNewline);
    printOut(text);
    return kExitOk;
  }
  return std::nullopt;
}

std::optional<double> numberOption(const QCommandLineParser& parser, const QString& name,
                                   double fallback) {
  if (!parser.isSet(name))
    return fallback;
  bool ok = false;
  const double value = parser.value(name).toDouble(&ok);
  if (!ok || !std::isfinite(value)) {
    printError(QStringLiteral("--%1: '%2' is not a number").arg(name, parser.value(name)));
    return std::nullopt;
  }
  return value;
}

void addOptions(QCommandLineParser& parser, const CliOptions& options) {
  for (const CliOption& option : options) {
    QString description = option.description;
    if (!option.defaultValue.isEmpty() && !description.contains(QStringLiteral("default")))
      description += QStringLiteral(" (default %1)").arg(option.defaultValue);
    parser.addOption(
        QCommandLineOption(option.name, description, option.valueName, option.defaultValue));
  }
}

QString missingOptions(const QCommandLineParser& parser, const QStringList& required) {
  QStringList missing;
  for (const QString& name : required) {
    if (!parser.isSet(name))
      missing << QStringLiteral("--") + name;
  }
  return missing.join(QStringLiteral(", "));
}

std::optional<int> integerOption(const QCommandLineParser& parser, const QString& name,
                                 int fallback, int minimum, int maximum) {
  if (!parser.isSet(name))
    return fallback;
  bool ok = false;
  const int value = parser.value(name).toInt(&ok);
  if (!ok || value < minimum || value > maximum) {
    const QString range = maximum == std::numeric_limits<int>::max()
                              ? QStringLiteral("of at least %1").arg(minimum)
                              : QStringLiteral("from %1 to %2").arg(minimum).arg(maximum);
    printError(
        QStringLiteral("--%1: '%2' is not a whole number %3").arg(name, parser.value(name), range));
    return std::nullopt;
  }
  return value;
}

CliOption jsonOption() {
  return {option::kJson,
          {},
          QStringLiteral("Print the result as one JSON object on standard output."),
          {}};
}

void printJson(const QJsonObject& object) {
  printOut(QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Compact)) +
           QLatin1Char('\n'));
}

CliOption strictOption(const QString& doing) {
  return {option::kStrict,
          {},
          QStringLiteral("Fail when the preset has problems (a missing or unreadable map, a "
                         "clamped value) instead of %1 what loaded.")
              .arg(doing),
          {}};
}

bool acceptPresetProblems(const std::vector<std::string>& problems, bool strict) {
  for (const std::string& problem : problems)
    printError((strict ? QString() : QStringLiteral("warning: ")) +
               QString::fromStdString(problem));
  return !strict || problems.empty();
}

QString prefixedBy(const QString& namedBy, const std::string& message) {
  const QString text = QString::fromStdString(message);
  return namedBy.isEmpty() ? text : namedBy + QStringLiteral(": ") + text;
}

std::optional<int> resolveMesh(const QString& meshName, core::Mesh& mesh, const QString& namedBy) {
  const std::string name = meshName.isEmpty() ? std::string("plane") : meshName.toStdString();
  if (const auto shape = core::findPrimitiveShape(name)) {
    mesh = core::makePrimitive(*shape);
    return std::nullopt;
  }
  if (QFileInfo(meshName).suffix().isEmpty() && !QFileInfo::exists(meshName)) {
    printError(QStringLiteral("%1 %2: expected %3, or a mesh file")
                   .arg(namedBy.isEmpty() ? QStringLiteral("--mesh") : namedBy, meshName,
                        enumNames(core::allPrimitiveShapes(), core::primitiveShapeName)));
    return kExitUsage;
  }
  core::Result<core::ImportedMesh> imported = core::importMesh(name);
  if (!imported) {
    printError(prefixedBy(namedBy, imported.error()));
    return kExitFailure;
  }
  mesh = std::move(imported->mesh);
  return std::nullopt;
}

}  // namespace relief::cli
