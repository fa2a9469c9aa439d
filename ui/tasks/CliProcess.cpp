// CliProcess; see CliProcess.h.
#include "ui/tasks/CliProcess.h"

#include <QCoreApplication>
#include <QDir>
#include <QJsonDocument>

namespace relief::ui::inline tasks {

CliProcess::CliProcess(QObject* parent) : QObject(parent), m_process(new QProcess(this)) {
  connectProcess();
}

void CliProcess::connectProcess() {
  connect(m_process, &QProcess::readyReadStandardError, this, &CliProcess::readProgress);
  connect(m_process, &QProcess::finished, this, &CliProcess::ended);
  connect(m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
    if (error == QProcess::FailedToStart)
      Q_EMIT failedToStart(tr("Cannot start %1: %2").arg(m_program, m_process->errorString()));
  });
}

CliProcess::~CliProcess() {
  abandon();
}

QString CliProcess::defaultProgram() {
  return QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("relief-cli"));
}

void CliProcess::abandon() {
  if (!running())
    return;
  // The old run's end must not be taken for a new one's.
  m_process->disconnect(this);
  m_process->kill();
  m_process->waitForFinished(2000);
  connectProcess();
}

void CliProcess::start(const QString& program, const QStringList& arguments) {
  abandon();
  m_program = program;
  m_errors.clear();
  m_pending.clear();
  m_process->start(program, arguments);
}

void CliProcess::cancel() {
  if (running())
    m_process->kill();  // ended() reports the cancel
}

void CliProcess::readProgress() {
  m_pending += m_process->readAllStandardError();
  // Whole lines: "progress 0.42" is reported, anything else is kept for the message.
  qsizetype end;
  while ((end = m_pending.indexOf('\n')) >= 0) {
    const QByteArray line = m_pending.left(end);
    m_pending.remove(0, end + 1);
    if (line.startsWith("progress "))
      Q_EMIT progress(line.mid(9).toDouble());
    else
      m_errors += line + '\n';
  }
}

void CliProcess::ended(int exitCode, QProcess::ExitStatus status) {
  readProgress();
  if (status == QProcess::CrashExit) {
    Q_EMIT cancelled();
    return;
  }
  const QJsonObject report = QJsonDocument::fromJson(m_process->readAllStandardOutput()).object();
  Q_EMIT finished(exitCode, report, QString::fromUtf8(m_errors + m_pending).trimmed());
}

}  // namespace relief::ui::inline tasks
