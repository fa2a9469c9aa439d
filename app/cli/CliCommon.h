// Shared pieces of relief-cli's commands: exit codes, printing, argument parsing helpers.
#pragma once

#include "core/mesh/Mesh.h"

#include <QCommandLineParser>
#include <QString>
#include <QStringList>

#include <optional>
#include <span>
#include <string_view>

namespace relief::cli {

// Exit codes: 0 success, 1 the work failed (a file, a render), 2 the command line is wrong.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

void printOut(const QString& text);
void printError(const QString& text);  // prefixed with "relief-cli: "

// Arguments as QStrings (argv decoded with the locale, as Qt does).
QStringList argumentsFrom(int argc, char* argv[]);

// Parses `arguments` (argv[0] and the command name first). Returns an exit code when parsing
// already decided the outcome: --help printed (0) or a usage error printed (2).
std::optional<int> parseOrExit(QCommandLineParser& parser, const QStringList& arguments,
                               const QString& usage);

// Parses a number option; prints an error naming the option and returns nullopt when bad.
std::optional<double> numberOption(const QCommandLineParser& parser, const QString& name,
                                   double fallback);

// A mesh by --mesh's value: a primitive's name (plane, cube, ...) or a mesh file; an empty
// name is the plane. Returns an exit code after printing the problem when it cannot be had.
std::optional<int> resolveMesh(const QString& meshName, core::Mesh& mesh);

// An enum's value names joined with '|', for help and error texts.
template <class Enum, class NameOf>
QString enumNames(std::span<const Enum> values, NameOf nameOf) {
  QStringList result;
  for (Enum value : values) {
    const std::string_view name = nameOf(value);
    result << QString::fromUtf8(name.data(), qsizetype(name.size()));
  }
  return result.join(QStringLiteral("|"));
}

}  // namespace relief::cli
