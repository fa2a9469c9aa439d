// Runs the relief-cli under test (the build's, RELIEF_CLI_PATH) as a process, for the CLI tests.
#pragma once

#include <QProcessEnvironment>
#include <QStringList>

#include <string>

namespace relief::test {

struct CliRun {
  int exitCode = -1;
  bool crashed = false;  // killed by a signal or timed out
  std::string out;
  std::string err;
};

// A path or word for a command line.
inline QString q(const std::string& text) {
  return QString::fromStdString(text);
}

CliRun runCli(const QStringList& arguments,
              const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment());

}  // namespace relief::test
