// Shared pieces of relief-cli's commands: exit codes, printing, argument parsing helpers.
#pragma once

#include "core/mesh/Mesh.h"

#include <QCommandLineParser>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

namespace relief::cli {

// Exit codes: 0 success, 1 the work failed (a file, a render), 2 the command line is wrong.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

void printOut(const QString& text);
// --quiet (any command): informational lines (what was written, notes) are not printed; results
// a command was asked for (info, --json, metrics) and errors and warnings on stderr still are.
void setQuiet(bool quiet);
bool quiet();
// Takes --quiet (or -q) out of argv wherever it stands after argv[0], and sets quiet() if it
// was there: it applies to every command, which then parses the rest.
void takeQuietFlag(int& argc, char* argv[]);
void printNote(const QString& text);  // printOut unless --quiet
// Core's names and labels (UTF-8 string views) as QStrings.
inline QString qstr(std::string_view text) {
  return QString::fromUtf8(text.data(), qsizetype(text.size()));
}
void printError(const QString& text);  // prefixed with "relief-cli: "

// While one exists, printError also keeps each message here (a batch reports each job's).
class ErrorCapture {
 public:
  ErrorCapture();
  ~ErrorCapture();
  ErrorCapture(const ErrorCapture&) = delete;
  ErrorCapture& operator=(const ErrorCapture&) = delete;
  const QStringList& messages() const { return m_messages; }

 private:
  friend void printError(const QString& text);
  ErrorCapture* m_outer;
  QStringList m_messages;
};

// Arguments as QStrings (argv decoded with the locale, as Qt does).
QStringList argumentsFrom(int argc, char* argv[]);

// Parses `arguments` (argv[0] and the command name first). Returns an exit code when parsing
// already decided the outcome: --help printed (0) or a usage error printed (2).
std::optional<int> parseOrExit(QCommandLineParser& parser, const QStringList& arguments,
                               const QString& usage);

// One option of a command, declared once: the command's table is what parsing and --help
// read. An empty valueName makes a flag; defaultValue is what value() returns when the option is
// not given (and --help says so).
struct CliOption {
  QString name;
  QString valueName;
  QString description;
  QString defaultValue;
};
using CliOptions = std::vector<CliOption>;

void addOptions(QCommandLineParser& parser, const CliOptions& options);

// Which of `required` are missing, as "--a, --b"; empty when all are given.
QString missingOptions(const QCommandLineParser& parser, const QStringList& required);

// A value from a table of named entries (anything with .name; `valueOf` picks the value, by
// default .value, e.g. core's export choices); prints "--option X: expected a|b|c" and returns
// nullopt when the option's value names none of them.
template <class Table, class ValueOf>
auto namedOption(const QCommandLineParser& parser, const QString& option, const Table& table,
                 ValueOf valueOf)
    -> std::optional<std::decay_t<decltype(valueOf(*std::begin(table)))>> {
  const QString given = parser.value(option);
  QStringList names;
  for (const auto& entry : table) {
    const QString name = qstr(entry.name);
    if (name == given)
      return valueOf(entry);
    names << name;
  }
  printError(
      QStringLiteral("--%1 %2: expected %3").arg(option, given, names.join(QLatin1Char('|'))));
  return std::nullopt;
}

template <class Table>
auto namedOption(const QCommandLineParser& parser, const QString& option, const Table& table) {
  return namedOption(parser, option, table, [](const auto& entry) { return entry.value; });
}

// Parses a number option; prints an error naming the option and returns nullopt when bad.
std::optional<double> numberOption(const QCommandLineParser& parser, const QString& name,
                                   double fallback);

// Parses a whole-number option within [minimum, maximum]; "0.5" or "1e3" is refused.
std::optional<int> integerOption(const QCommandLineParser& parser, const QString& name,
                                 int fallback, int minimum, int maximum);

// --json, for the commands that report a result: one JSON object on standard output instead
// of the text lines (printed with printJson, --quiet or not).
CliOption jsonOption();
void printJson(const QJsonObject& object);

// --strict, for the commands that read a preset and otherwise carry on past its problems (a
// missing or unreadable map, a clamped value): `doing` is what they do ("exporting").
CliOption strictOption(const QString& doing);

// Prints a loaded preset's problems: as warnings, or under --strict as errors. Returns false
// when --strict refuses the preset because it had any.
bool acceptPresetProblems(const std::vector<std::string>& problems, bool strict);

// A mesh by --mesh's value: a primitive's name (plane, cube, ...) or a mesh file; an empty
// name is the plane. Returns an exit code after printing the problem when it cannot be had.
// `namedBy` says where a name that did not come from --mesh was read ("m.relief: view.mesh"),
// so that a bad file's message names the preset and the field as well as the file.
std::optional<int> resolveMesh(const QString& meshName, core::Mesh& mesh,
                               const QString& namedBy = {});

// "<namedBy>: <message>", or the message alone when `namedBy` is empty.
QString prefixedBy(const QString& namedBy, const std::string& message);

// An enum's value names joined with '|', for help and error texts.
template <class Enum, class NameOf>
QString enumNames(std::span<const Enum> values, NameOf nameOf) {
  QStringList result;
  for (const auto& value : values)
    result << qstr(nameOf(value));
  return result.join(QStringLiteral("|"));
}

}  // namespace relief::cli
