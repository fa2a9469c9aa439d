// CliProcess: runs `relief-cli` as a child process for the work that renders offscreen (Choose
// for Me, Compare All's rendered error). The child has a GL context of its own, off the editor's
// GUI thread, and a crash there cannot take the editor down. It reads the child's
// "progress 0.42" lines (--progress-lines) as they come, keeps the rest of its standard error
// for the message, and hands back its JSON report (--json) when it ends.
#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QObject>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace relief::ui::inline tasks {

class CliProcess : public QObject {
  Q_OBJECT

 public:
  explicit CliProcess(QObject* parent = nullptr);
  ~CliProcess() override;  // kills a child still running

  // relief-cli beside the editor's executable (where both are installed and built).
  static QString defaultProgram();

  // Starts `program arguments`; cancels a run still going (its `finished` is not emitted).
  void start(const QString& program, const QStringList& arguments);
  void cancel();   // kills the child; `cancelled` follows
  void abandon();  // kills the child and waits for it; nothing follows (a new run replaces it)
  bool running() const { return m_process->state() != QProcess::NotRunning; }

 Q_SIGNALS:
  void progress(double fraction);
  // The child ended by itself: its exit code, its JSON report (empty when it printed none) and
  // its standard error less the progress lines, trimmed.
  void finished(int exitCode, const QJsonObject& report, const QString& errors);
  void cancelled();
  void failedToStart(const QString& message);

 private:
  void connectProcess();
  void readProgress();
  void ended(int exitCode, QProcess::ExitStatus status);

  QProcess* m_process;
  QString m_program;
  QByteArray m_errors;   // the run's standard error, less its progress lines
  QByteArray m_pending;  // the start of a line not yet complete
};

}  // namespace relief::ui::inline tasks
