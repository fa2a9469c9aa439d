// BatchCommand; see BatchCommand.h.
#include "BatchCommand.h"

#include "app/cli/CliOptionNames.h"

#include "CliCommands.h"
#include "CliCommon.h"
#include "TerminalProgress.h"

#include "core/base/InputFile.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <optional>
#include <vector>

namespace relief::cli {
namespace {

// A manifest of a million jobs is a mistake, not a batch.
constexpr std::uintmax_t kMaxBatchFileBytes = std::uintmax_t(64) << 20;

struct Job {
  int line = 0;
  QStringList words;  // the command's name, then its arguments
};

// A line's words as a POSIX shell splits them: blanks separate, '...' is literal, "..." keeps
// blanks and takes \ before " \ $ `, and \ outside quotes takes the next character. No
// expansion of any kind. Empty when a quote is left open (`open` set).
QStringList splitShellWords(const QString& line, bool& open) {
  QStringList words;
  QString word;
  bool inWord = false;
  open = false;
  for (qsizetype i = 0; i < line.size(); ++i) {
    const QChar c = line[i];
    if (c == QLatin1Char(' ') || c == QLatin1Char('\t')) {
      if (inWord)
        words << word;
      word.clear();
      inWord = false;
      continue;
    }
    inWord = true;
    if (c == QLatin1Char('\\') && i + 1 < line.size()) {
      word += line[++i];
    } else if (c == QLatin1Char('\'') || c == QLatin1Char('"')) {
      const qsizetype close = [&] {
        for (qsizetype j = i + 1; j < line.size(); ++j) {
          if (c == QLatin1Char('"') && line[j] == QLatin1Char('\\') && j + 1 < line.size() &&
              QStringLiteral("\"\\$`").contains(line[j + 1])) {
            word += line[++j];
            continue;
          }
          if (line[j] == c)
            return j;
          word += line[j];
        }
        return qsizetype(-1);
      }();
      if (close < 0) {
        open = true;
        return {};
      }
      i = close;
    } else {
      word += c;
    }
  }
  if (inWord)
    words << word;
  return words;
}

// The jobs of `path`, or the first problem, as "FILE:LINE: what".
std::optional<QString> readJobs(const QString& path, std::vector<Job>& jobs) {
  const core::Result<std::uintmax_t> readable =
      core::checkInputFile(path.toStdString(), kMaxBatchFileBytes, "batch file");
  if (!readable)
    return QString::fromStdString(readable.error());
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
    return path + QStringLiteral(": cannot be read (") + file.errorString() + QStringLiteral(")");
  int lineNumber = 0;
  while (!file.atEnd()) {
    ++lineNumber;
    const QString line = QString::fromUtf8(file.readLine()).trimmed();
    if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
      continue;
    const QString where = QStringLiteral("%1:%2: ").arg(path).arg(lineNumber);
    Job job{lineNumber, {}};
    if (line.startsWith(QLatin1Char('['))) {
      QJsonParseError error{};
      const QJsonDocument document = QJsonDocument::fromJson(line.toUtf8(), &error);
      if (!document.isArray())
        return where + QStringLiteral("not a JSON array of strings (") + error.errorString() +
               QStringLiteral(")");
      for (const QJsonValue& word : document.array()) {
        if (!word.isString())
          return where + QStringLiteral("the JSON array holds something other than strings");
        job.words << word.toString();
      }
    } else {
      bool open = false;
      job.words = splitShellWords(line, open);
      if (open)
        return where + QStringLiteral("a quote is not closed");
    }
    if (job.words.isEmpty())
      return where + QStringLiteral("an empty job");
    const QString& name = job.words.front();
    if (name == QLatin1String("batch"))
      return where + QStringLiteral("a batch cannot run another batch");
    if (!findCliCommand(name))
      return where + QStringLiteral("unknown command '%1'").arg(name);
    jobs.push_back(std::move(job));
  }
  return std::nullopt;
}

// What the job works on, for the progress line: its first argument that names a file.
QString jobLabel(const Job& job) {
  for (const QString& word : job.words.mid(1)) {
    if (!word.startsWith(QLatin1Char('-')) && word.contains(QLatin1Char('.')))
      return job.words.front() + QLatin1Char(' ') + word.section(QLatin1Char('/'), -1);
  }
  return job.words.front();
}

}  // namespace

int runBatch(const QStringList& arguments, JobRunner renderJob) {
  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "Run many jobs in one process. FILE holds one job per line: a relief-cli command line "
      "without 'relief-cli' (quoted as in a shell) or a JSON array of its words; blank lines "
      "and lines starting with # are skipped. Jobs run in order; a failed job fails alone, and "
      "the batch exits 1 when any failed."));
  parser.addPositionalArgument(QStringLiteral("file"), QStringLiteral("The jobs, one a line."));
  addOptions(parser, {jsonOption()});
  if (auto exit = parseOrExit(parser, arguments,
                              QStringLiteral("relief-cli batch FILE [--json] [--quiet]")))
    return *exit;
  if (parser.positionalArguments().size() != 1) {
    printError(QStringLiteral("batch takes one file of jobs"));
    return kExitUsage;
  }
  const QString path = parser.positionalArguments().front();
  std::vector<Job> jobs;
  if (const std::optional<QString> problem = readJobs(path, jobs)) {
    printError(QStringLiteral("batch: ") + *problem);
    return kExitUsage;
  }
  // render jobs, and compare --rendered (a render), run in the render session.
  const auto isRender = [](const Job& job) {
    return job.words.front() == QLatin1String("render") ||
           (job.words.front() == QLatin1String("compare") &&
            job.words.contains(QStringLiteral("--rendered")));
  };
  if (!renderJob && std::any_of(jobs.begin(), jobs.end(), isRender))
    return kBatchNeedsRenderer;

  const bool json = parser.isSet(option::kJson);
  // With --json, standard output is the summary alone: the jobs' notes ("wrote ...") are held
  // back; their errors still go to standard error.
  if (json)
    setQuiet(true);
  QJsonArray reports;
  int failed = 0;
  const int total = int(jobs.size());
  for (int k = 0; k < total; ++k) {
    const Job& job = jobs[std::size_t(k)];
    {
      // Redrawn between jobs; a long job's own progress line takes its place while it runs.
      TerminalProgress progress(
          QStringLiteral("batch %1/%2 %3").arg(k + 1).arg(total).arg(jobLabel(job)));
      progress.control().report(double(k) / double(total));
    }
    const JobRunner run = isRender(job) ? renderJob : findCliCommand(job.words.front())->run;
    ErrorCapture errors;
    const int exitCode = run(QStringList{arguments.front()} + job.words);
    if (exitCode != kExitOk) {
      ++failed;
      printError(QStringLiteral("batch: %1:%2: the job failed (exit code %3): %4")
                     .arg(path)
                     .arg(job.line)
                     .arg(exitCode)
                     .arg(job.words.join(QLatin1Char(' '))));
    }
    if (json) {
      QJsonObject report;
      report.insert(QStringLiteral("line"), job.line);
      report.insert(QStringLiteral("arguments"), QJsonArray::fromStringList(job.words));
      report.insert(QStringLiteral("exit"), exitCode);
      // The job's own messages (the last is the batch's line above, for failed jobs).
      QStringList messages = errors.messages();
      if (exitCode != kExitOk && !messages.isEmpty())
        messages.removeLast();
      report.insert(QStringLiteral("errors"), QJsonArray::fromStringList(messages));
      reports.append(report);
    }
  }
  if (json) {
    QJsonObject summary;
    summary.insert(QStringLiteral("batch"), path);
    summary.insert(QStringLiteral("jobs"), reports);
    summary.insert(QStringLiteral("succeeded"), total - failed);
    summary.insert(QStringLiteral("failed"), failed);
    printJson(summary);
  } else {
    printNote(QStringLiteral("batch: %1 jobs, %2 succeeded, %3 failed\n")
                  .arg(total)
                  .arg(total - failed)
                  .arg(failed));
  }
  return failed > 0 ? kExitFailure : kExitOk;
}

}  // namespace relief::cli
