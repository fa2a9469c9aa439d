// `relief-cli batch FILE`: many jobs in one process. FILE holds one job per line, each a
// relief-cli command line without the program's name (words split as a shell splits them,
// quotes included) or a JSON array of those words; blank lines and lines starting with # are
// skipped. The jobs run in order, each with every core (the encoders and generators are
// parallel), sharing the thread pool and, for render jobs, one GL context. A failed job fails
// alone: its message names its file (and the batch names the line), the next job runs, and the
// batch exits 1 if any job failed. --json prints each job's exit code and messages at the end.
#pragma once

#include <QStringList>

namespace relief::cli {

// One job's command, in process. `arguments` are argv[0], the command's name, then its own.
using JobRunner = int (*)(const QStringList& arguments);

// What runBatch returns when the file holds render jobs and `renderJob` is null: the caller
// runs the batch again where rendering is linked (relief-cli-render).
constexpr int kBatchNeedsRenderer = -1;

// `arguments` as for any command ("relief-cli", "batch", FILE, options). `renderJob` runs a
// render job, or is null where rendering is not linked.
int runBatch(const QStringList& arguments, JobRunner renderJob);

}  // namespace relief::cli
