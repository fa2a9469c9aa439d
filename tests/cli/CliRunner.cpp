// CliRunner; see CliRunner.h.
#include "cli/CliRunner.h"

#include <QProcess>

namespace relief::test {

CliRun runCli(const QStringList& arguments, const QProcessEnvironment& environment) {
  QProcess process;
  process.setProcessEnvironment(environment);
  process.start(QStringLiteral(RELIEF_CLI_PATH), arguments);
  CliRun run;
  if (!process.waitForFinished(120000)) {
    process.kill();
    run.crashed = true;
    return run;
  }
  run.crashed = process.exitStatus() != QProcess::NormalExit;
  run.exitCode = process.exitCode();
  run.out = process.readAllStandardOutput().toStdString();
  run.err = process.readAllStandardError().toStdString();
  return run;
}

}  // namespace relief::test
