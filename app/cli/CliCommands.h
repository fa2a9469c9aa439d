// The table of relief-cli's commands (name, summary, entry point), read by dispatch, the usage
// text, and `relief-cli batch`, which runs the same entry points in one process. render is in
// the table by name only: it runs in relief-cli-render (RenderHelper.h), which links GL.
#pragma once

#include "BatchCommand.h"

#include <QString>

#include <span>

namespace relief::cli {

struct CliCommand {
  const char* name;
  const char* summary;
  JobRunner run;  // null for render, which runs in relief-cli-render
};

std::span<const CliCommand> cliCommands();
const CliCommand* findCliCommand(const QString& name);

}  // namespace relief::cli
